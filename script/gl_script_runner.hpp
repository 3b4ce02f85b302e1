#pragma once
// Executes a parsed GL script on a GLContext, call by call, reporting GL
// errors, pass boundaries and snapshot points to the caller.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"

namespace mpr {

struct ScriptHooks {
  std::function<void(const ScriptCommand& call)> beforeCall;
  std::function<void(const ScriptCommand& pass)> onPass;
  std::function<void(const ScriptCommand& snapshot, const GLContext&)> onSnapshot;
  // An @expect or @expect-picture: the buffers as they are at that line.
  std::function<void(const ScriptCommand& probe, const GLContext&)> onProbe;
  // A call GL rejected: the call had no effect and `error` is what glGetError returns.
  std::function<void(const ScriptCommand& call, std::uint32_t error)> onGLError;
};

// "LINE: GL_INVALID_ENUM in glStencilFunc": how a GL error is reported.
std::string glErrorReport(const ScriptCommand& call, std::uint32_t error);

// One call or directive on the context (no error reporting).
void executeCall(GLContext& gl, const ScriptCommand& call);

class GLEmulator;

// Executes commands one at a time, as runScript does (for a streamed script,
// see streamScript): execute each in order, then finish once.
class ScriptExecutor {
 public:
  ScriptExecutor(GLContext& gl, const ScriptHooks& hooks);
  ~ScriptExecutor();
  void execute(const ScriptCommand& cmd);
  // A call given by its parts, as execute runs it, without a command made
  // for it (streamScriptAhead's packed calls): false, and nothing run, when
  // a beforeCall hook needs the command itself.
  bool executeCall(GLCall call, int line, std::span<const ScriptArg> args);
  // Closes an open draw; returns the number of GL errors raised.
  std::size_t finish();

 private:
  // The GL error the call just run raised, if any: counted and reported
  // (with `whole`, the command it came as; else one made of its parts).
  void countError(GLCall call, int line, std::span<const ScriptArg> args, const ScriptCommand* whole);

  GLContext& gl_;
  const ScriptHooks& hooks_;
  std::unique_ptr<GLEmulator> emulator_;
  std::size_t errors_ = 0;
};

// Runs every command; returns the number of GL errors raised. `commands`
// limits the run to the first so many (a pixel's history up to a probe).
std::size_t runScript(const Script& script, GLContext& gl, const ScriptHooks& hooks = {},
                      std::size_t commands = static_cast<std::size_t>(-1));

}  // namespace mpr
