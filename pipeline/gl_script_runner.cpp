#include "pipeline/gl_script_runner.hpp"

#include <GL/gl.h>

#include "pipeline/gl_dispatch.hpp"
#include "pipeline/gl_emulator.hpp"
#include "pipeline/gl_enums.hpp"

namespace mpr {
// Calls GL forbids between glBegin and glEnd raise GL_INVALID_OPERATION in the
// context methods themselves (GL 1.1 section 2.6.3).
std::string glErrorReport(const ScriptCommand& c, std::uint32_t error) {
  return std::to_string(c.line) + ": " + std::string(glErrorName(error)) + " in " + std::string(glCallName(c.call));
}

namespace {
// Calls that may join the open GL_QUADS draw (GLContext::flushVertices):
// vertex attributes, glEnd, and further GL_QUADS blocks. Before any other
// command the runner closes that draw, so that its fragments belong to the
// call, pass and snapshot that made them.
bool mayJoinQuadDraw(const ScriptCommand& c) {
  if (c.kind != ScriptCommand::Kind::Call) return false;
  switch (c.call) {
    case GLCall::Begin: return !c.args.empty() && c.args[0].bits == GL_QUADS;
    case GLCall::Color3f: case GLCall::Color4f: case GLCall::Color3ub: case GLCall::Color4ub:
    case GLCall::Normal3f: case GLCall::Materialf: case GLCall::Materialfv:
    case GLCall::Vertex2f: case GLCall::Vertex3f: case GLCall::Vertex4f:
    case GLCall::End: case GLCall::Rectf:
      return true;
    default:
      return false;
  }
}
}  // namespace

void executeCall(GLContext& gl, const ScriptCommand& cmd) {
  GLEmulator emulator(gl);
  dispatch(emulator, cmd);
}

std::size_t runScript(const Script& script, GLContext& gl, const ScriptHooks& hooks, std::size_t commands) {
  std::size_t errors = 0;
  GLEmulator emulator(gl);
  for (std::size_t i = 0; i < script.commands.size() && i < commands; ++i) {
    const ScriptCommand& cmd = script.commands[i];
    // glBegin of another mode closes the quad draw but is no flush of the
    // vbo (its vertex format stays).
    if (cmd.kind == ScriptCommand::Kind::Call && cmd.call == GLCall::Begin) gl.closeQuadDraw();
    else if (!mayJoinQuadDraw(cmd)) gl.flushVertices();
    switch (cmd.kind) {
      case ScriptCommand::Kind::WindowMap:
      case ScriptCommand::Kind::FragmentCount:
        dispatch(emulator, cmd);
        break;
      case ScriptCommand::Kind::Pass:
        if (hooks.onPass) hooks.onPass(cmd);
        break;
      case ScriptCommand::Kind::Snapshot:
        if (hooks.onSnapshot) hooks.onSnapshot(cmd, gl);
        break;
      case ScriptCommand::Kind::Probe:
        if (hooks.onProbe) hooks.onProbe(cmd, gl);
        break;
      case ScriptCommand::Kind::Call: {
        if (hooks.beforeCall) hooks.beforeCall(cmd);
        dispatch(emulator, cmd);
        const std::uint32_t e = gl.getError();
        if (e != GL_NO_ERROR) {
          ++errors;
          if (hooks.onGLError) hooks.onGLError(cmd, e);
        }
        break;
      }
    }
  }
  gl.flushVertices();
  return errors;
}

}  // namespace mpr
