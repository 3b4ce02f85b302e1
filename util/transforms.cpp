#include "util/transforms.hpp"

#include <cmath>

namespace mpr {
namespace {
constexpr double kPi = 3.14159265358979323846;
// m[col][row] in GLM; M(row, col) as Mesa writes it.
float& at(Mat4& m, int row, int col) { return m[col][row]; }
}  // namespace

Mat4 matrixFromColumnMajor(const float v[16]) {
  Mat4 m(1.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = v[c * 4 + r];
  return m;
}

Mat4 translationMatrix(float x, float y, float z) {
  Mat4 m(1.0f);
  m[3] = Vec4(x, y, z, 1.0f);
  return m;
}

Mat4 scaleMatrix(float x, float y, float z) {
  Mat4 m(1.0f);
  m[0][0] = x;
  m[1][1] = y;
  m[2][2] = z;
  return m;
}

Mat4 rotationMatrix(float angle, float x, float y, float z) {
  // Mesa 22.3 (_math_matrix_rotate): the angle in radians rounded to float,
  // then sinf / cosf of it (measured: a glRotatef probe on llvmpipe matched
  // on 100 % of pixels this way, 89.6 % with double sine and cosine); exact
  // axis rotations when the axis is a coordinate axis.
  const float radians = static_cast<float>(angle * kPi / 180.0);
  const float s = std::sin(radians);
  const float c = std::cos(radians);
  Mat4 m(1.0f);
  if (x == 0.0f && y == 0.0f && z != 0.0f) {
    at(m, 0, 0) = c;
    at(m, 1, 1) = c;
    at(m, 0, 1) = z < 0.0f ? s : -s;
    at(m, 1, 0) = z < 0.0f ? -s : s;
    return m;
  }
  if (x == 0.0f && z == 0.0f && y != 0.0f) {
    at(m, 0, 0) = c;
    at(m, 2, 2) = c;
    at(m, 0, 2) = y < 0.0f ? -s : s;
    at(m, 2, 0) = y < 0.0f ? s : -s;
    return m;
  }
  if (y == 0.0f && z == 0.0f && x != 0.0f) {
    at(m, 1, 1) = c;
    at(m, 2, 2) = c;
    at(m, 1, 2) = x < 0.0f ? s : -s;
    at(m, 2, 1) = x < 0.0f ? -s : s;
    return m;
  }
  const float mag = std::sqrt(x * x + y * y + z * z);
  if (!(mag > 1.0e-4f)) return m;
  x /= mag;
  y /= mag;
  z /= mag;
  const float xx = x * x, yy = y * y, zz = z * z, xy = x * y, yz = y * z, zx = z * x;
  const float xs = x * s, ys = y * s, zs = z * s, oneC = 1.0f - c;
  at(m, 0, 0) = (oneC * xx) + c;
  at(m, 0, 1) = (oneC * xy) - zs;
  at(m, 0, 2) = (oneC * zx) + ys;
  at(m, 1, 0) = (oneC * xy) + zs;
  at(m, 1, 1) = (oneC * yy) + c;
  at(m, 1, 2) = (oneC * yz) - xs;
  at(m, 2, 0) = (oneC * zx) - ys;
  at(m, 2, 1) = (oneC * yz) + xs;
  at(m, 2, 2) = (oneC * zz) + c;
  return m;
}

std::optional<Mat4> frustumMatrix(float l, float r, float b, float t, float n, float f) {
  if (n <= 0.0f || f <= 0.0f || n == f || l == r || t == b) return std::nullopt;
  Mat4 m(0.0f);
  at(m, 0, 0) = (2.0f * n) / (r - l);
  at(m, 0, 2) = (r + l) / (r - l);
  at(m, 1, 1) = (2.0f * n) / (t - b);
  at(m, 1, 2) = (t + b) / (t - b);
  at(m, 2, 2) = -(f + n) / (f - n);
  at(m, 2, 3) = -(2.0f * f * n) / (f - n);
  at(m, 3, 2) = -1.0f;
  return m;
}

std::optional<Mat4> orthoMatrix(float l, float r, float b, float t, float n, float f) {
  if (l == r || b == t || n == f) return std::nullopt;
  Mat4 m(1.0f);
  at(m, 0, 0) = 2.0f / (r - l);
  at(m, 0, 3) = -(r + l) / (r - l);
  at(m, 1, 1) = 2.0f / (t - b);
  at(m, 1, 3) = -(t + b) / (t - b);
  at(m, 2, 2) = -2.0f / (f - n);
  at(m, 2, 3) = -(f + n) / (f - n);
  return m;
}

std::optional<Mat4> perspectiveMatrix(double fovy, double aspect, double zNear, double zFar) {
  // SGI libGLU: double precision, then glMultMatrixd (which stores floats).
  const double radians = fovy / 2 * kPi / 180;
  const double deltaZ = zFar - zNear;
  const double sine = std::sin(radians);
  if (deltaZ == 0 || sine == 0 || aspect == 0) return std::nullopt;
  const double cotangent = std::cos(radians) / sine;
  Mat4 m(0.0f);
  m[0][0] = static_cast<float>(cotangent / aspect);
  m[1][1] = static_cast<float>(cotangent);
  m[2][2] = static_cast<float>(-(zFar + zNear) / deltaZ);
  m[2][3] = -1.0f;
  m[3][2] = static_cast<float>(-2 * zNear * zFar / deltaZ);
  return m;
}

namespace {
void normalize3(float v[3]) {
  const float r = static_cast<float>(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  if (r == 0.0f) return;
  v[0] /= r;
  v[1] /= r;
  v[2] /= r;
}
void cross3(const float a[3], const float b[3], float out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
}  // namespace

Mat4 lookAtMatrix(double ex, double ey, double ez, double cx, double cy, double cz, double ux,
                  double uy, double uz) {
  // SGI libGLU: float vectors, glMultMatrixf, then glTranslated(-eye).
  float forward[3] = {static_cast<float>(cx - ex), static_cast<float>(cy - ey), static_cast<float>(cz - ez)};
  float up[3] = {static_cast<float>(ux), static_cast<float>(uy), static_cast<float>(uz)};
  float side[3];
  normalize3(forward);
  cross3(forward, up, side);
  normalize3(side);
  cross3(side, forward, up);
  Mat4 m(1.0f);
  for (int i = 0; i < 3; ++i) {
    m[i][0] = side[i];
    m[i][1] = up[i];
    m[i][2] = -forward[i];
  }
  return multiply(m, translationMatrix(static_cast<float>(-ex), static_cast<float>(-ey),
                                       static_cast<float>(-ez)));
}

}  // namespace mpr
