// GLContext: matrix stacks, GL and GLU matrix calls, user clip planes.
#include <GL/gl.h>

#include <cmath>
#include <cstring>

#include "pipeline/gl/gl_context.hpp"
#include "pipeline/draw/mesa_matrix_inverse.hpp"
#include "util/transforms.hpp"

namespace mpr {

MatrixStack& GLContext::currentStack() { return matrixMode_ == GL_PROJECTION ? projection_ : modelview_; }

namespace {
bool sameBits(const Mat4& a, const Mat4& b) { return std::memcmp(&a, &b, sizeof(Mat4)) == 0; }
}  // namespace

// Mesa's matrix calls (matrix.c), measured call by call against llvmpipe:
// glMatrixMode and glPushMatrix never flush the stored vertices; glLoadMatrix
// flushes only when the matrix differs bit for bit, glMultMatrix (and so the
// two GLU calls, one glMultMatrixd each) only when its matrix is not the
// identity, glPopMatrix only when the top changed since the push and differs
// from the one below; the others always flush.
void GLContext::setTop(const Mat4& m, unsigned addedFlags) {
  flushVertices();
  MatrixStack& stack = currentStack();
  stack.top() = m;
  stack.markChanged();
  // matrix_multf, _math_matrix_translate, _math_matrix_scale: the call's
  // geometry flags, the class and inverse to be found again.
  stack.mesaTop().flags |= addedFlags | mesa_matrix::kDirtyType | mesa_matrix::kDirtyInverse;
}

void GLContext::multiplyTop(const Mat4& m) {
  if (m == Mat4(1.0f)) return;  // compared by value: -0 is 0
  // _math_matrix_mul_floats: general, classified again from the entries.
  setTop(multiply(currentStack().top(), m), mesa_matrix::kGeneral | mesa_matrix::kDirtyFlags);
}

void GLContext::analyseMatrices(bool modelview, bool projection) {
  if (modelview) modelview_.analyse();
  if (projection) projection_.analyse();
}

void GLContext::matrixMode(GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION) return setError(GL_INVALID_ENUM);
  matrixMode_ = mode;
}

void GLContext::loadIdentity() {
  if (!checkOutsideBeginEnd()) return;
  setTop(Mat4(1.0f), 0);
  // _math_matrix_set_identity: the identity class and inverse, and only the
  // dirty bits cleared: the geometry flags of earlier calls stay.
  MesaMatrixState& mesa = currentStack().mesaTop();
  mesa.flags &= ~mesa_matrix::kDirty;
  mesa.type = MatrixClass::Identity;
  mesa.inverse = Mat4(1.0f);
}

void GLContext::loadMatrix(const float m[16]) {
  if (!checkOutsideBeginEnd()) return;
  const Mat4 loaded = matrixFromColumnMajor(m);
  if (sameBits(loaded, currentStack().top())) return;
  setTop(loaded, 0);
  currentStack().mesaTop().flags = mesa_matrix::kGeneral | mesa_matrix::kDirty;  // _math_matrix_loadf
}

void GLContext::multMatrix(const float m[16]) {
  if (!checkOutsideBeginEnd()) return;
  multiplyTop(matrixFromColumnMajor(m));
}

void GLContext::pushMatrix() {
  if (!checkOutsideBeginEnd()) return;
  if (!currentStack().push()) setError(GL_STACK_OVERFLOW);
}

void GLContext::popMatrix() {
  if (!checkOutsideBeginEnd()) return;
  MatrixStack& stack = currentStack();
  if (stack.depth() <= 1) return setError(GL_STACK_UNDERFLOW);
  if (stack.changedSincePush() && !sameBits(stack.top(), stack.below())) flushVertices();
  stack.pop();
}

void GLContext::translate(float x, float y, float z) {
  if (!checkOutsideBeginEnd()) return;
  setTop(multiply(currentStack().top(), translationMatrix(x, y, z)), mesa_matrix::kTranslation);
}

void GLContext::rotate(float angle, float x, float y, float z) {
  if (!checkOutsideBeginEnd()) return;
  // _mesa_Rotatef flushes, then leaves the matrix (and its flags) alone for
  // a zero angle, as _math_matrix_rotate does for a short axis that is not
  // a coordinate axis.
  const bool axisAligned = (x == 0.0f) + (y == 0.0f) + (z == 0.0f) == 2;
  if (angle == 0.0f || (!axisAligned && std::sqrt(x * x + y * y + z * z) <= 1.0e-4f)) return flushVertices();
  setTop(multiply(currentStack().top(), rotationMatrix(angle, x, y, z)), mesa_matrix::kRotation);
}

void GLContext::scale(float x, float y, float z) {
  if (!checkOutsideBeginEnd()) return;
  const bool uniform = std::fabs(x - y) < 1e-8f && std::fabs(x - z) < 1e-8f;
  setTop(multiply(currentStack().top(), scaleMatrix(x, y, z)),
         uniform ? mesa_matrix::kUniformScale : mesa_matrix::kGeneralScale);
}

void GLContext::frustum(double l, double r, double b, double t, double n, double f) {
  if (!checkOutsideBeginEnd()) return;
  if (n <= 0.0 || f <= 0.0 || n == f || l == r || b == t) return setError(GL_INVALID_VALUE);
  const auto m = frustumMatrix(static_cast<float>(l), static_cast<float>(r), static_cast<float>(b),
                               static_cast<float>(t), static_cast<float>(n), static_cast<float>(f));
  if (!m) return setError(GL_INVALID_VALUE);
  setTop(multiply(currentStack().top(), *m), mesa_matrix::kPerspective);
}

void GLContext::ortho(double l, double r, double b, double t, double n, double f) {
  if (!checkOutsideBeginEnd()) return;
  if (l == r || b == t || n == f) return setError(GL_INVALID_VALUE);
  const auto m = orthoMatrix(static_cast<float>(l), static_cast<float>(r), static_cast<float>(b),
                             static_cast<float>(t), static_cast<float>(n), static_cast<float>(f));
  if (!m) return setError(GL_INVALID_VALUE);
  setTop(multiply(currentStack().top(), *m), mesa_matrix::kGeneralScale | mesa_matrix::kTranslation);
}

void GLContext::perspective(double fovy, double aspect, double zNear, double zFar) {
  if (!checkOutsideBeginEnd()) return;
  // GLU silently does nothing for a degenerate frustum.
  if (const auto m = perspectiveMatrix(fovy, aspect, zNear, zFar)) multiplyTop(*m);
}

void GLContext::lookAt(double ex, double ey, double ez, double cx, double cy, double cz, double ux,
                       double uy, double uz) {
  if (!checkOutsideBeginEnd()) return;
  multiplyTop(lookAtMatrix(ex, ey, ez, cx, cy, cz, ux, uy, uz));
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
  const ClipPlane eye = mesaTransformRowVector(p, modelview_.analysedInverse());
  if (!changing(eye == clipPlanesEye_[plane - GL_CLIP_PLANE0])) return;  // TEST_EQ_4V
  clipPlanesEye_[plane - GL_CLIP_PLANE0] = eye;
  if (clipPlaneEnabled_[plane - GL_CLIP_PLANE0]) analyseMatrices(false, true);  // _mesa_update_clip_plane
}

}  // namespace mpr
