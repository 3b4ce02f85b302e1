#include "stepper/pixel_history.hpp"

#include <sstream>

#include "script/gl_script_runner.hpp"
#include "stepper/pixel_event_recorder.hpp"
#include "stepper/pixel_history_text.hpp"
#include "stepper/script_passes.hpp"

namespace mpr {

std::string recordPixelHistory(const Script& script, GLContext& gl, int x, int y, std::size_t commands) {
  const std::vector<ScriptPass> passes = scriptPasses(script);
  std::ostringstream history;
  int headerPass = -1;
  PixelEventRecorder recorder(gl, PixelRect{x, y, x + 1, y + 1}, [&](const PixelEvent& e, const FragmentState& s) {
    if (e.pass != headerPass) {
      history << passHeaderLine(e.pass, passes[static_cast<std::size_t>(e.pass)].label) << "\n";
      headerPass = e.pass;
    }
    history << pixelEventLine(e, s) << "\n";
  });
  ScriptHooks hooks;
  hooks.beforeCall = [&](const ScriptCommand& c) { recorder.beforeCall(c); };
  hooks.onPass = [&](const ScriptCommand&) { recorder.startPass(); };
  runScript(script, gl, hooks, commands);
  recorder.finish();
  return history.str();
}

}  // namespace mpr
