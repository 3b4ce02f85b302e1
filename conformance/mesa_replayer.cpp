#include "conformance/mesa_replayer.hpp"

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdlib>
#include <memory>

#include "pipeline/gl_script_runner.hpp"
#include "pipeline/transforms.hpp"

namespace mpr {
namespace {

BufferSet readBuffers(const std::string& point, int w, int h) {
  BufferSet b;
  b.point = point;
  b.width = w;
  b.height = h;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  b.color.resize(n * 4);
  b.depth.resize(n);
  b.stencil.resize(n);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
  // 24-bit depth as the top bits of a 32-bit unsigned read.
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b.depth.data());
  for (std::uint32_t& z : b.depth) z >>= 8;
  glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b.stencil.data());
  return b;
}

void multMatrix(const Mat4& m) { glMultMatrixf(&m[0][0]); }

void execute(const ScriptCommand& c) {
  const auto& a = c.args;
  auto f = [&](size_t i) { return static_cast<GLfloat>(a[i].number); };
  auto d = [&](size_t i) { return static_cast<GLdouble>(a[i].number); };
  auto i32 = [&](size_t i) { return static_cast<GLint>(static_cast<std::int32_t>(a[i].bits)); };
  auto u = [&](size_t i) { return static_cast<GLenum>(a[i].bits); };
  auto b = [&](size_t i) { return static_cast<GLboolean>(a[i].bits != 0); };
  GLfloat v[16] = {};
  for (size_t i = 0; i < a.size() && i < 16; ++i) v[i] = f(i);
  GLdouble vd[16] = {};
  for (size_t i = 0; i < a.size() && i < 16; ++i) vd[i] = d(i);
  switch (c.call) {
    case GLCall::Viewport: return glViewport(i32(0), i32(1), i32(2), i32(3));
    case GLCall::Scissor: return glScissor(i32(0), i32(1), i32(2), i32(3));
    case GLCall::ClearColor: return glClearColor(f(0), f(1), f(2), f(3));
    case GLCall::ClearDepth: return glClearDepth(d(0));
    case GLCall::ClearStencil: return glClearStencil(i32(0));
    case GLCall::ClearAccum: return glClearAccum(f(0), f(1), f(2), f(3));
    case GLCall::Clear: return glClear(u(0));
    case GLCall::ColorMask: return glColorMask(b(0), b(1), b(2), b(3));
    case GLCall::DepthMask: return glDepthMask(b(0));
    case GLCall::StencilMask: return glStencilMask(u(0));
    case GLCall::Finish: return glFinish();
    case GLCall::Flush: return glFlush();
    case GLCall::Enable: return glEnable(u(0));
    case GLCall::Disable: return glDisable(u(0));
    case GLCall::StencilFunc: return glStencilFunc(u(0), i32(1), u(2));
    case GLCall::StencilOp: return glStencilOp(u(0), u(1), u(2));
    case GLCall::DepthFunc: return glDepthFunc(u(0));
    case GLCall::DepthRange: return glDepthRange(d(0), d(1));
    case GLCall::BlendFunc: return glBlendFunc(u(0), u(1));
    case GLCall::AlphaFunc: return glAlphaFunc(u(0), f(1));
    case GLCall::CullFace: return glCullFace(u(0));
    case GLCall::FrontFace: return glFrontFace(u(0));
    case GLCall::ShadeModel: return glShadeModel(u(0));
    case GLCall::Fogf: return glFogf(u(0), f(1));
    case GLCall::Fogi: return glFogi(u(0), i32(1));
    case GLCall::Fogfv: return glFogfv(u(0), v + 1);
    case GLCall::Hint: return glHint(u(0), u(1));
    case GLCall::MatrixMode: return glMatrixMode(u(0));
    case GLCall::LoadIdentity: return glLoadIdentity();
    case GLCall::LoadMatrixf: return glLoadMatrixf(v);
    case GLCall::LoadMatrixd: return glLoadMatrixd(vd);
    case GLCall::MultMatrixf: return glMultMatrixf(v);
    case GLCall::MultMatrixd: return glMultMatrixd(vd);
    case GLCall::PushMatrix: return glPushMatrix();
    case GLCall::PopMatrix: return glPopMatrix();
    case GLCall::Translatef: return glTranslatef(f(0), f(1), f(2));
    case GLCall::Translated: return glTranslated(d(0), d(1), d(2));
    case GLCall::Rotatef: return glRotatef(f(0), f(1), f(2), f(3));
    case GLCall::Rotated: return glRotated(d(0), d(1), d(2), d(3));
    case GLCall::Scalef: return glScalef(f(0), f(1), f(2));
    case GLCall::Scaled: return glScaled(d(0), d(1), d(2));
    case GLCall::Frustum: return glFrustum(d(0), d(1), d(2), d(3), d(4), d(5));
    case GLCall::Ortho: return glOrtho(d(0), d(1), d(2), d(3), d(4), d(5));
    case GLCall::Perspective:
      // SGI GLU's construction, multiplied as GLU does (glMultMatrixd).
      if (const auto m = perspectiveMatrix(d(0), d(1), d(2), d(3))) multMatrix(*m);
      return;
    case GLCall::LookAt: return multMatrix(lookAtMatrix(d(0), d(1), d(2), d(3), d(4), d(5), d(6), d(7), d(8)));
    case GLCall::ClipPlane: { const GLdouble eq[4] = {d(1), d(2), d(3), d(4)}; return glClipPlane(u(0), eq); }
    case GLCall::Lightf: return glLightf(u(0), u(1), f(2));
    case GLCall::Lightfv: return glLightfv(u(0), u(1), v + 2);
    case GLCall::LightModelf: return glLightModelf(u(0), f(1));
    case GLCall::LightModelfv: return glLightModelfv(u(0), v + 1);
    case GLCall::LightModeli: return glLightModeli(u(0), i32(1));
    case GLCall::Materialf: return glMaterialf(u(0), u(1), f(2));
    case GLCall::Materialfv: return glMaterialfv(u(0), u(1), v + 2);
    case GLCall::ColorMaterial: return glColorMaterial(u(0), u(1));
    case GLCall::Color3f: return glColor3f(f(0), f(1), f(2));
    case GLCall::Color4f: return glColor4f(f(0), f(1), f(2), f(3));
    case GLCall::Color3ub: return glColor3ub(static_cast<GLubyte>(u(0)), static_cast<GLubyte>(u(1)), static_cast<GLubyte>(u(2)));
    case GLCall::Color4ub:
      return glColor4ub(static_cast<GLubyte>(u(0)), static_cast<GLubyte>(u(1)), static_cast<GLubyte>(u(2)),
                        static_cast<GLubyte>(u(3)));
    case GLCall::Normal3f: return glNormal3f(f(0), f(1), f(2));
    case GLCall::Begin: return glBegin(u(0));
    case GLCall::End: return glEnd();
    case GLCall::Vertex2f: return glVertex2f(f(0), f(1));
    case GLCall::Vertex3f: return glVertex3f(f(0), f(1), f(2));
    case GLCall::Vertex4f: return glVertex4f(f(0), f(1), f(2), f(3));
    case GLCall::Rectf: return glRectf(f(0), f(1), f(2), f(3));
    case GLCall::Accum: return glAccum(u(0), f(1));
  }
}

struct ContextDeleter {
  void operator()(osmesa_context* c) const { OSMesaDestroyContext(c); }
};

}  // namespace

MesaReplay replayOnMesa(const Script& script, const std::string& driver) {
  // Mesa reads GALLIUM_DRIVER when the context's screen is created.
  setenv("GALLIUM_DRIVER", driver.c_str(), 1);
  std::unique_ptr<osmesa_context, ContextDeleter> ctx(OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr));
  if (!ctx) throw MesaUnavailable("OSMesa could not create an RGBA context with 24/8/16 bits (" + driver + ")");
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(script.width) * script.height * 4);
  if (!OSMesaMakeCurrent(ctx.get(), pixels.data(), GL_UNSIGNED_BYTE, script.width, script.height))
    throw MesaUnavailable("OSMesaMakeCurrent failed");
  OSMesaPixelStore(OSMESA_Y_UP, 1);

  MesaReplay out;
  if (const GLubyte* r = glGetString(GL_RENDERER)) out.renderer = reinterpret_cast<const char*>(r);
  bool inBegin = false;
  for (const ScriptCommand& c : script.commands) {
    if (c.kind == ScriptCommand::Kind::Snapshot) {
      glFinish();
      out.snapshots.push_back(readBuffers(c.label, script.width, script.height));
      continue;
    }
    if (c.kind != ScriptCommand::Kind::Call) continue;
    execute(c);
    if (c.call == GLCall::Begin) inBegin = true;
    if (c.call == GLCall::End) inBegin = false;
    // glGetError is itself an error between glBegin and glEnd.
    if (!inBegin)
      for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
        out.glErrors.push_back(glErrorReport(c, e));
  }
  glFinish();
  out.snapshots.push_back(readBuffers("final", script.width, script.height));
  return out;
}

}  // namespace mpr
