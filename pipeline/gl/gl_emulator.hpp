#pragma once
// The emulated pipeline behind the typed GL API: each call of the table on
// the GLContext, with no text in between.
#include "pipeline/gl/gl_api.hpp"
#include "pipeline/gl/gl_context.hpp"

namespace mpr {

class GLEmulator final : public GLApi {
 public:
  explicit GLEmulator(GLContext& gl) : gl_(gl) {}
  GLContext& context() { return gl_; }
  const GLContext& context() const { return gl_; }

  void viewport(GLint x, GLint y, GLsizei w, GLsizei h) override { gl_.viewport(x, y, w, h); }
  void scissor(GLint x, GLint y, GLsizei w, GLsizei h) override { gl_.scissor(x, y, w, h); }
  void clearColor(GLfloat r, GLfloat g, GLfloat b, GLfloat a) override { gl_.clearColor(r, g, b, a); }
  void clearDepth(GLdouble d) override { gl_.clearDepth(d); }
  void clearStencil(GLint s) override { gl_.clearStencil(s); }
  void clearAccum(GLfloat r, GLfloat g, GLfloat b, GLfloat a) override { gl_.clearAccum(r, g, b, a); }
  void clear(GLbitfield mask) override { gl_.clear(mask); }
  void colorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) override {
    gl_.colorMask(r != 0, g != 0, b != 0, a != 0);
  }
  void depthMask(GLboolean flag) override { gl_.depthMask(flag != 0); }
  void stencilMask(GLuint mask) override { gl_.stencilMask(mask); }
  void finish() override { gl_.finish(); }
  void flush() override { gl_.flush(); }
  void enable(GLenum cap) override { gl_.enable(cap); }
  void disable(GLenum cap) override { gl_.disable(cap); }
  void stencilFunc(GLenum func, GLint ref, GLuint mask) override { gl_.stencilFunc(func, ref, mask); }
  void stencilOp(GLenum sfail, GLenum dpfail, GLenum dppass) override { gl_.stencilOp(sfail, dpfail, dppass); }
  void depthFunc(GLenum func) override { gl_.depthFunc(func); }
  void depthRange(GLdouble n, GLdouble f) override { gl_.depthRange(n, f); }
  void blendFunc(GLenum src, GLenum dst) override { gl_.blendFunc(src, dst); }
  void alphaFunc(GLenum func, GLfloat ref) override { gl_.alphaFunc(func, ref); }
  void cullFace(GLenum mode) override { gl_.cullFace(mode); }
  void frontFace(GLenum mode) override { gl_.frontFace(mode); }
  void shadeModel(GLenum mode) override { gl_.shadeModel(mode); }
  void fogf(GLenum pname, GLfloat param) override { gl_.fogf(pname, param); }
  void fogi(GLenum pname, GLint param) override { gl_.fogi(pname, param); }
  // A pointer holds the values its pname takes (the script parser checks
  // their count), as in GL.
  void fogfv(GLenum pname, const GLfloat* params) override { gl_.fogfv(pname, params, 16); }
  void hint(GLenum target, GLenum mode) override { gl_.hint(target, mode); }
  void matrixMode(GLenum mode) override { gl_.matrixMode(mode); }
  void loadIdentity() override { gl_.loadIdentity(); }
  // The emulated matrix stacks are single precision (the Iris's): the double
  // calls convert on entry.
  void loadMatrixf(const GLfloat* m) override { gl_.loadMatrix(m); }
  void loadMatrixd(const GLdouble* m) override { gl_.loadMatrix(toFloats(m).data()); }
  void multMatrixf(const GLfloat* m) override { gl_.multMatrix(m); }
  void multMatrixd(const GLdouble* m) override { gl_.multMatrix(toFloats(m).data()); }
  void pushMatrix() override { gl_.pushMatrix(); }
  void popMatrix() override { gl_.popMatrix(); }
  void translatef(GLfloat x, GLfloat y, GLfloat z) override { gl_.translate(x, y, z); }
  void translated(GLdouble x, GLdouble y, GLdouble z) override { gl_.translate(f(x), f(y), f(z)); }
  void rotatef(GLfloat a, GLfloat x, GLfloat y, GLfloat z) override { gl_.rotate(a, x, y, z); }
  void rotated(GLdouble a, GLdouble x, GLdouble y, GLdouble z) override { gl_.rotate(f(a), f(x), f(y), f(z)); }
  void scalef(GLfloat x, GLfloat y, GLfloat z) override { gl_.scale(x, y, z); }
  void scaled(GLdouble x, GLdouble y, GLdouble z) override { gl_.scale(f(x), f(y), f(z)); }
  void frustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble fa) override {
    gl_.frustum(l, r, b, t, n, fa);
  }
  void ortho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble fa) override {
    gl_.ortho(l, r, b, t, n, fa);
  }
  void perspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) override {
    gl_.perspective(fovy, aspect, zNear, zFar);
  }
  void lookAt(GLdouble ex, GLdouble ey, GLdouble ez, GLdouble cx, GLdouble cy, GLdouble cz, GLdouble ux,
              GLdouble uy, GLdouble uz) override {
    gl_.lookAt(ex, ey, ez, cx, cy, cz, ux, uy, uz);
  }
  void clipPlane(GLenum plane, const GLdouble* equation) override { gl_.clipPlane(plane, equation); }
  void lightf(GLenum light, GLenum pname, GLfloat param) override { gl_.lightf(light, pname, param); }
  void lightfv(GLenum light, GLenum pname, const GLfloat* params) override { gl_.lightfv(light, pname, params, 16); }
  void lightModelf(GLenum pname, GLfloat param) override { gl_.lightModelf(pname, param); }
  void lightModelfv(GLenum pname, const GLfloat* params) override { gl_.lightModelfv(pname, params, 16); }
  void lightModeli(GLenum pname, GLint param) override { gl_.lightModeli(pname, param); }
  void materialf(GLenum face, GLenum pname, GLfloat param) override { gl_.materialf(face, pname, param); }
  void materialfv(GLenum face, GLenum pname, const GLfloat* params) override {
    gl_.materialfv(face, pname, params, 16);
  }
  void colorMaterial(GLenum face, GLenum mode) override { gl_.colorMaterial(face, mode); }
  void color3f(GLfloat r, GLfloat g, GLfloat b) override { gl_.color3f(r, g, b); }
  void color4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) override { gl_.color4f(r, g, b, a); }
  // Mesa's vbo_attrib_tmp.h TAG(Color3ub) is ATTR4F(..., 1.0): alpha 1 as
  // GL 1.1 says, and a four-component colour in the vbo's vertex format (a
  // wrap where the block had three; color3ub_wrap.gls).
  void color3ub(GLubyte r, GLubyte g, GLubyte b) override { gl_.color4f(r / 255.0f, g / 255.0f, b / 255.0f, 1.0f); }
  void color4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) override { gl_.color4ub(r, g, b, a); }
  void normal3f(GLfloat x, GLfloat y, GLfloat z) override { gl_.normal3f(x, y, z); }
  void begin(GLenum mode) override { gl_.begin(mode); }
  void end() override { gl_.end(); }
  void vertex2f(GLfloat x, GLfloat y) override { gl_.vertex4f(x, y, 0.0f, 1.0f, 2); }
  void vertex3f(GLfloat x, GLfloat y, GLfloat z) override { gl_.vertex4f(x, y, z, 1.0f, 3); }
  void vertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) override { gl_.vertex4f(x, y, z, w); }
  void rectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) override { gl_.rectf(x1, y1, x2, y2); }
  void accum(GLenum op, GLfloat value) override { gl_.accum(op, value); }

  void pass(std::string_view) override {}
  void windowMap(const std::optional<glm::mat3>& map) override { gl_.setWindowMap(map); }
  void beginFragmentCount() override { countStart_ = gl_.counters().fragmentsWritten; }
  std::uint64_t endFragmentCount() override { return gl_.counters().fragmentsWritten - countStart_; }

 private:
  static float f(double v) { return static_cast<float>(v); }
  static std::array<float, 16> toFloats(const GLdouble* m) {
    std::array<float, 16> out;
    for (int i = 0; i < 16; ++i) out[static_cast<std::size_t>(i)] = f(m[i]);
    return out;
  }
  GLContext& gl_;
  std::uint64_t countStart_ = 0;
};

}  // namespace mpr
