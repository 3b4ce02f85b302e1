#include "stepper/script_test.hpp"

#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script_runner.hpp"
#include "stepper/pixel_history.hpp"
#include "stepper/pixel_history_text.hpp"

namespace mpr {
namespace {

// Thrown from the probe hook to end the run at the first failure.
struct ProbeFailed {};

}  // namespace

ScriptTestResult runScriptTest(const Script& script, const HardwareProfile& profile) {
  ScriptTestResult r;
  r.probes = script.probeCount();
  r.width = script.width;
  r.height = script.height;
  std::size_t failedAt = 0;
  {
    GLContext gl(script.width, script.height, profile);
    ScriptHooks hooks;
    hooks.onGLError = [&](const ScriptCommand&, std::uint32_t) { ++r.glErrors; };
    hooks.onProbe = [&](const ScriptCommand& c, const GLContext& ctx) {
      ++r.probesRun;
      const ProbeOutcome o = evaluateProbe(*c.probe, ctx.framebuffer());
      if (o.passed) return;
      r.passed = false;
      r.failed = &c;
      r.message = o.message;
      r.x = o.x;
      r.y = o.y;
      r.difference = probeDifferenceImage(*c.probe, ctx.framebuffer());
      throw ProbeFailed{};
    };
    try {
      runScript(script, gl, hooks);
    } catch (const ProbeFailed&) {
      failedAt = static_cast<std::size_t>(r.failed - script.commands.data());
    }
  }
  if (r.passed) return r;
  // A second run, recording the failing pixel up to the probe: recording
  // costs nothing in the first run, which most scripts pass.
  GLContext gl(script.width, script.height, profile);
  r.history = recordPixelHistory(script, gl, r.x, r.y, failedAt);
  r.history += "at line " + std::to_string(r.failed->line) + ": " +
               pixelValueText(gl.stencilAt(r.x, r.y), profile.stencilBits, gl.depthAt(r.x, r.y), gl.colorAt(r.x, r.y)) +
               "\n";
  return r;
}

}  // namespace mpr
