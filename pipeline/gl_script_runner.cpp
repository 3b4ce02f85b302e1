#include "pipeline/gl_script_runner.hpp"

#include <GL/gl.h>

#include "pipeline/gl_enums.hpp"

namespace mpr {
// Calls GL forbids between glBegin and glEnd raise GL_INVALID_OPERATION in the
// context methods themselves (GL 1.1 section 2.6.3).
std::string glErrorReport(const ScriptCommand& c, std::uint32_t error) {
  return std::to_string(c.line) + ": " + std::string(glErrorName(error)) + " in " + std::string(glCallName(c.call));
}

void executeCall(GLContext& gl, const ScriptCommand& cmd) {
  const auto& a = cmd.args;
  auto f = [&](size_t i) { return static_cast<float>(a[i].number); };
  auto d = [&](size_t i) { return a[i].number; };
  auto i32 = [&](size_t i) { return static_cast<int>(static_cast<std::int32_t>(a[i].bits)); };
  auto u = [&](size_t i) { return a[i].bits; };
  auto floats = [&](size_t from, float* out) {
    int n = 0;
    for (size_t i = from; i < a.size() && n < 16; ++i) out[n++] = f(i);
    return n;
  };
  float v[16] = {};

  switch (cmd.call) {
    case GLCall::Viewport: return gl.viewport(i32(0), i32(1), i32(2), i32(3));
    case GLCall::Scissor: return gl.scissor(i32(0), i32(1), i32(2), i32(3));
    case GLCall::ClearColor: return gl.clearColor(f(0), f(1), f(2), f(3));
    case GLCall::ClearDepth: return gl.clearDepth(d(0));
    case GLCall::ClearStencil: return gl.clearStencil(i32(0));
    case GLCall::ClearAccum: return gl.clearAccum(f(0), f(1), f(2), f(3));
    case GLCall::Clear: return gl.clear(u(0));
    case GLCall::ColorMask: return gl.colorMask(u(0) != 0, u(1) != 0, u(2) != 0, u(3) != 0);
    case GLCall::DepthMask: return gl.depthMask(u(0) != 0);
    case GLCall::StencilMask: return gl.stencilMask(u(0));
    case GLCall::Finish: return gl.finish();
    case GLCall::Flush: return gl.flush();
    case GLCall::Enable: return gl.enable(u(0));
    case GLCall::Disable: return gl.disable(u(0));
    case GLCall::StencilFunc: return gl.stencilFunc(u(0), i32(1), u(2));
    case GLCall::StencilOp: return gl.stencilOp(u(0), u(1), u(2));
    case GLCall::DepthFunc: return gl.depthFunc(u(0));
    case GLCall::DepthRange: return gl.depthRange(d(0), d(1));
    case GLCall::BlendFunc: return gl.blendFunc(u(0), u(1));
    case GLCall::AlphaFunc: return gl.alphaFunc(u(0), f(1));
    case GLCall::CullFace: return gl.cullFace(u(0));
    case GLCall::FrontFace: return gl.frontFace(u(0));
    case GLCall::ShadeModel: return gl.shadeModel(u(0));
    case GLCall::Fogf: return gl.fogf(u(0), f(1));
    case GLCall::Fogi: return gl.fogi(u(0), i32(1));
    case GLCall::Fogfv: { const int n = floats(1, v); return gl.fogfv(u(0), v, n); }
    case GLCall::Hint: return gl.hint(u(0), u(1));
    case GLCall::MatrixMode: return gl.matrixMode(u(0));
    case GLCall::LoadIdentity: return gl.loadIdentity();
    case GLCall::LoadMatrixf: case GLCall::LoadMatrixd: floats(0, v); return gl.loadMatrix(v);
    case GLCall::MultMatrixf: case GLCall::MultMatrixd: floats(0, v); return gl.multMatrix(v);
    case GLCall::PushMatrix: return gl.pushMatrix();
    case GLCall::PopMatrix: return gl.popMatrix();
    case GLCall::Translatef: case GLCall::Translated: return gl.translate(f(0), f(1), f(2));
    case GLCall::Rotatef: case GLCall::Rotated: return gl.rotate(f(0), f(1), f(2), f(3));
    case GLCall::Scalef: case GLCall::Scaled: return gl.scale(f(0), f(1), f(2));
    case GLCall::Frustum: return gl.frustum(d(0), d(1), d(2), d(3), d(4), d(5));
    case GLCall::Ortho: return gl.ortho(d(0), d(1), d(2), d(3), d(4), d(5));
    case GLCall::Perspective: return gl.perspective(d(0), d(1), d(2), d(3));
    case GLCall::LookAt: return gl.lookAt(d(0), d(1), d(2), d(3), d(4), d(5), d(6), d(7), d(8));
    case GLCall::ClipPlane: { const double eq[4] = {d(1), d(2), d(3), d(4)}; return gl.clipPlane(u(0), eq); }
    case GLCall::Lightf: return gl.lightf(u(0), u(1), f(2));
    case GLCall::Lightfv: { const int n = floats(2, v); return gl.lightfv(u(0), u(1), v, n); }
    case GLCall::LightModelf: return gl.lightModelf(u(0), f(1));
    case GLCall::LightModelfv: { const int n = floats(1, v); return gl.lightModelfv(u(0), v, n); }
    case GLCall::LightModeli: return gl.lightModeli(u(0), i32(1));
    case GLCall::Materialf: return gl.materialf(u(0), u(1), f(2));
    case GLCall::Materialfv: { const int n = floats(2, v); return gl.materialfv(u(0), u(1), v, n); }
    case GLCall::ColorMaterial: return gl.colorMaterial(u(0), u(1));
    case GLCall::Color3f: return gl.color4f(f(0), f(1), f(2), 1.0f);
    case GLCall::Color4f: return gl.color4f(f(0), f(1), f(2), f(3));
    case GLCall::Color3ub:
      return gl.color4ub(static_cast<std::uint8_t>(u(0)), static_cast<std::uint8_t>(u(1)), static_cast<std::uint8_t>(u(2)), 255);
    case GLCall::Color4ub:
      return gl.color4ub(static_cast<std::uint8_t>(u(0)), static_cast<std::uint8_t>(u(1)), static_cast<std::uint8_t>(u(2)),
                         static_cast<std::uint8_t>(u(3)));
    case GLCall::Normal3f: return gl.normal3f(f(0), f(1), f(2));
    case GLCall::Begin: return gl.begin(u(0));
    case GLCall::End: return gl.end();
    case GLCall::Vertex2f: return gl.vertex4f(f(0), f(1), 0.0f, 1.0f);
    case GLCall::Vertex3f: return gl.vertex4f(f(0), f(1), f(2), 1.0f);
    case GLCall::Vertex4f: return gl.vertex4f(f(0), f(1), f(2), f(3));
    case GLCall::Rectf: return gl.rectf(f(0), f(1), f(2), f(3));
    case GLCall::Accum: return gl.accum(u(0), f(1));
  }
}

std::size_t runScript(const Script& script, GLContext& gl, const ScriptHooks& hooks) {
  std::size_t errors = 0;
  for (const ScriptCommand& cmd : script.commands) {
    switch (cmd.kind) {
      case ScriptCommand::Kind::Pass:
        if (hooks.onPass) hooks.onPass(cmd);
        break;
      case ScriptCommand::Kind::Snapshot:
        if (hooks.onSnapshot) hooks.onSnapshot(cmd, gl);
        break;
      case ScriptCommand::Kind::Call: {
        if (hooks.beforeCall) hooks.beforeCall(cmd);
        executeCall(gl, cmd);
        const std::uint32_t e = gl.getError();
        if (e != GL_NO_ERROR) {
          ++errors;
          if (hooks.onGLError) hooks.onGLError(cmd, e);
        }
        break;
      }
    }
  }
  return errors;
}

}  // namespace mpr
