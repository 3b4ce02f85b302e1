#include "script/gl_script_runner.hpp"

#include <GL/gl.h>

#include "script/gl_dispatch.hpp"
#include "pipeline/gl/gl_emulator.hpp"
#include "pipeline/gl/gl_enums.hpp"

namespace mpr {
// Calls GL forbids between glBegin and glEnd raise GL_INVALID_OPERATION in the
// context methods themselves (GL 1.1 section 2.6.3).
std::string glErrorReport(const ScriptCommand& c, std::uint32_t error) {
  return std::to_string(c.line) + ": " + std::string(glErrorName(error)) + " in " + std::string(glCallName(c.call));
}


void executeCall(GLContext& gl, const ScriptCommand& cmd) {
  GLEmulator emulator(gl);
  dispatch(emulator, cmd);
}

ScriptExecutor::ScriptExecutor(GLContext& gl, const ScriptHooks& hooks)
    : gl_(gl), hooks_(hooks), emulator_(std::make_unique<GLEmulator>(gl)) {}

ScriptExecutor::~ScriptExecutor() = default;

void ScriptExecutor::execute(const ScriptCommand& cmd) {
  // No flush here: the context flushes where Mesa does (a call that changes
  // state, a read of the buffers), so a script runs exactly as mpr conform
  // replays it on MPR. Fragments of a GL_QUADS draw still open (Mesa's vbo
  // merging blocks, GLContext::drawQuadsPiece) land at the call that closes it.
  switch (cmd.kind) {
    case ScriptCommand::Kind::WindowMap:
      dispatch(*emulator_, cmd);
      break;
    case ScriptCommand::Kind::FragmentCount:
      // Nothing in a replay reads the count: the decisions the render took
      // from it are already the calls that follow. Taking it would wait for
      // the row threads to finish every queued draw, twice per count.
      break;
    case ScriptCommand::Kind::Pass:
      if (hooks_.onPass) hooks_.onPass(cmd);
      break;
    case ScriptCommand::Kind::Snapshot:
      gl_.prepareRead();
      if (hooks_.onSnapshot) hooks_.onSnapshot(cmd, gl_);
      break;
    case ScriptCommand::Kind::Probe:
      if (hooks_.onProbe) hooks_.onProbe(cmd, gl_);
      break;
    case ScriptCommand::Kind::Call: {
      if (hooks_.beforeCall) hooks_.beforeCall(cmd);
      dispatch(*emulator_, cmd);
      countError(cmd.call, cmd.line, cmd.args, &cmd);
      break;
    }
  }
}

bool ScriptExecutor::executeCall(GLCall call, int line, std::span<const ScriptArg> args) {
  if (hooks_.beforeCall) return false;
  // A trace's vertices and normals (nine in ten of its calls) called on the
  // emulator directly, not through dispatchCall's table and argument tuple;
  // the parser has checked their counts.
  const auto number = [&](std::size_t i) { return static_cast<GLfloat>(args[i].number); };
  if (call == GLCall::Vertex3f && args.size() == 3) emulator_->vertex3f(number(0), number(1), number(2));
  else if (call == GLCall::Normal3f && args.size() == 3) emulator_->normal3f(number(0), number(1), number(2));
  else dispatchCall(*emulator_, call, args);
  countError(call, line, args, nullptr);
  return true;
}

void ScriptExecutor::countError(GLCall call, int line, std::span<const ScriptArg> args, const ScriptCommand* whole) {
  const std::uint32_t e = gl_.getError();
  if (e == GL_NO_ERROR) return;
  ++errors_;
  if (!hooks_.onGLError) return;
  if (whole) return hooks_.onGLError(*whole, e);
  ScriptCommand cmd;  // made only for the report
  cmd.line = line;
  cmd.call = call;
  cmd.args.assign(args.begin(), args.end());
  hooks_.onGLError(cmd, e);
}

std::size_t ScriptExecutor::finish() {
  gl_.flushVertices();
  return errors_;
}

std::size_t runScript(const Script& script, GLContext& gl, const ScriptHooks& hooks, std::size_t commands) {
  ScriptExecutor executor(gl, hooks);
  for (std::size_t i = 0; i < script.commands.size() && i < commands; ++i) executor.execute(script.commands[i]);
  return executor.finish();
}

}  // namespace mpr
