#pragma once
// The matrices of GL's and GLU's matrix calls, built in single precision in the
// same order of operations as Mesa's math/m_matrix.c and SGI's libGLU, so that
// a script replayed on Mesa sees the very same matrix bits.
#include <optional>

#include "util/vecmath.hpp"

namespace mpr {

Mat4 translationMatrix(float x, float y, float z);
Mat4 scaleMatrix(float x, float y, float z);
// Rotation by `degrees` about (x, y, z); identity when the axis is shorter than 1e-4.
Mat4 rotationMatrix(float degrees, float x, float y, float z);
// Empty when GL would raise GL_INVALID_VALUE (near or far <= 0 for a frustum,
// left == right, bottom == top, near == far).
std::optional<Mat4> frustumMatrix(float l, float r, float b, float t, float n, float f);
std::optional<Mat4> orthoMatrix(float l, float r, float b, float t, float n, float f);
// gluPerspective: empty when GLU returns without effect (zero depth range,
// zero sine, zero aspect).
std::optional<Mat4> perspectiveMatrix(double fovyDegrees, double aspect, double zNear, double zFar);
// gluLookAt: the rotation followed by the translation by -eye.
Mat4 lookAtMatrix(double ex, double ey, double ez, double cx, double cy, double cz, double ux,
                  double uy, double uz);

// Column-major 16 numbers (glLoadMatrix order) to a matrix.
Mat4 matrixFromColumnMajor(const float m[16]);

// A * B, with Mesa's summation order (identical to GLM's).
inline Mat4 multiply(const Mat4& a, const Mat4& b) { return a * b; }

}  // namespace mpr
