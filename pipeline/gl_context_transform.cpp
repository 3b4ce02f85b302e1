// GLContext: matrix stacks, GL and GLU matrix calls, user clip planes.
#include <GL/gl.h>

#include <cmath>

#include "pipeline/gl_context.hpp"
#include "pipeline/mesa_matrix_inverse.hpp"
#include "util/transforms.hpp"

namespace mpr {

MatrixStack& GLContext::currentStack() { return matrixMode_ == GL_PROJECTION ? projection_ : modelview_; }

void GLContext::matrixMode(GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION) return setError(GL_INVALID_ENUM);
  matrixMode_ = mode;
}

void GLContext::loadIdentity() {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = Mat4(1.0f);
}

void GLContext::loadMatrix(const float m[16]) {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = matrixFromColumnMajor(m);
}

void GLContext::multMatrix(const float m[16]) {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = multiply(currentStack().top(), matrixFromColumnMajor(m));
}

void GLContext::pushMatrix() {
  if (!checkOutsideBeginEnd()) return;
  if (!currentStack().push()) setError(GL_STACK_OVERFLOW);
}

void GLContext::popMatrix() {
  if (!checkOutsideBeginEnd()) return;
  if (!currentStack().pop()) setError(GL_STACK_UNDERFLOW);
}

void GLContext::translate(float x, float y, float z) {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = multiply(currentStack().top(), translationMatrix(x, y, z));
}

void GLContext::rotate(float angle, float x, float y, float z) {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = multiply(currentStack().top(), rotationMatrix(angle, x, y, z));
}

void GLContext::scale(float x, float y, float z) {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = multiply(currentStack().top(), scaleMatrix(x, y, z));
}

void GLContext::frustum(double l, double r, double b, double t, double n, double f) {
  if (!checkOutsideBeginEnd()) return;
  if (n <= 0.0 || f <= 0.0 || n == f || l == r || b == t) return setError(GL_INVALID_VALUE);
  const auto m = frustumMatrix(static_cast<float>(l), static_cast<float>(r), static_cast<float>(b),
                               static_cast<float>(t), static_cast<float>(n), static_cast<float>(f));
  if (!m) return setError(GL_INVALID_VALUE);
  currentStack().top() = multiply(currentStack().top(), *m);
}

void GLContext::ortho(double l, double r, double b, double t, double n, double f) {
  if (!checkOutsideBeginEnd()) return;
  if (l == r || b == t || n == f) return setError(GL_INVALID_VALUE);
  const auto m = orthoMatrix(static_cast<float>(l), static_cast<float>(r), static_cast<float>(b),
                             static_cast<float>(t), static_cast<float>(n), static_cast<float>(f));
  if (!m) return setError(GL_INVALID_VALUE);
  currentStack().top() = multiply(currentStack().top(), *m);
}

void GLContext::perspective(double fovy, double aspect, double zNear, double zFar) {
  if (!checkOutsideBeginEnd()) return;
  // GLU silently does nothing for a degenerate frustum.
  if (const auto m = perspectiveMatrix(fovy, aspect, zNear, zFar))
    currentStack().top() = multiply(currentStack().top(), *m);
}

void GLContext::lookAt(double ex, double ey, double ez, double cx, double cy, double cz, double ux,
                       double uy, double uz) {
  if (!checkOutsideBeginEnd()) return;
  currentStack().top() = multiply(currentStack().top(), lookAtMatrix(ex, ey, ez, cx, cy, cz, ux, uy, uz));
}

void GLContext::clipPlane(GLenumValue plane, const double eq[4]) {
  if (!checkOutsideBeginEnd()) return;
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + 6) return setError(GL_INVALID_ENUM);
  // GL 1.1 section 2.11: the plane is stored in eye coordinates, transformed by
  // the inverse of the modelview matrix current when it is specified.
  const Vec4 p(static_cast<float>(eq[0]), static_cast<float>(eq[1]), static_cast<float>(eq[2]),
               static_cast<float>(eq[3]));
  // Through the inverse Mesa keeps (m_matrix.c) and _mesa_transform_vector's
  // sums, so that llvmpipe's clipper and MPR's cut at the same place.
  clipPlanesEye_[plane - GL_CLIP_PLANE0] = mesaTransformRowVector(p, mesaInverse(modelview_.top()));
}

}  // namespace mpr
