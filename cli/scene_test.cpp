#include "cli/scene_test.hpp"

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/scene_renderer.hpp"
#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "stepper/pixel_history.hpp"
#include "stepper/pixel_history_text.hpp"

namespace mpr::cli {
namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// The pixel's history up to the end of pass `pass` (as mpr step counts
// passes; past the last: the finished render), from the render's trace.
std::string pixelHistory(const Scene& scene, int pass, int x, int y) {
  const HardwareProfile profile = *findProfile(scene.render.profile);
  Script script;
  {
    GLContext gl(scene.render.width, scene.render.height, profile);
    GLCommandStream stream(gl, true);
    renderScene(scene, stream);
    script = parseScript(stream.trace(), scene.file + " (its render's GL calls)");
  }
  std::size_t stop = script.commands.size();
  int passes = 0;
  for (std::size_t i = 0; i < script.commands.size(); ++i)
    if (script.commands[i].kind == ScriptCommand::Kind::Pass && ++passes == pass + 1) {
      stop = i;
      break;
    }
  GLContext gl(scene.render.width, scene.render.height, profile);
  std::string h = recordPixelHistory(script, gl, x, y, stop);
  h += (stop == script.commands.size() ? std::string("in the finished render") : "at the end of pass " + std::to_string(pass)) +
       ": " + pixelValueText(gl.stencilAt(x, y), profile.stencilBits, gl.depthAt(x, y), gl.colorAt(x, y)) + "\n";
  return h;
}

}  // namespace

SceneTestResult sceneTestResult(const Scene& scene, const SceneExpectationWatcher& watcher, bool history) {
  SceneTestResult r;
  r.expectations = scene.expectations.size();
  r.width = scene.render.width;
  r.height = scene.render.height;
  for (int i : watcher.unmatched()) {
    const SceneExpectation& e = scene.expectations[static_cast<std::size_t>(i)];
    std::string which = "no pass";
    if (e.level >= 0) which += " of level " + std::to_string(e.level);
    if (e.light >= 0) which += std::string(e.level >= 0 ? "," : "") + " of light " + std::to_string(e.light);
    const int seen = watcher.matches(static_cast<std::size_t>(i));
    const std::string found = seen == 0 ? "matched " + which
                                        : "matched " + std::to_string(seen) + " pass" + (seen == 1 ? "" : "es") +
                                              ", not " + std::to_string(e.occurrence);
    r.errors.push_back(scene.file + ":" + std::to_string(e.afterLine) + ":" + std::to_string(e.afterColumn) +
                       ": after " + quoted(e.after) + " " + found + " of the render (" +
                       std::to_string(watcher.passes()) + " passes; mpr step " + scene.file + " lists them)");
  }
  const int f = watcher.firstFailure();
  if (f < 0) return r;
  const SceneExpectation& e = scene.expectations[static_cast<std::size_t>(f)];
  const ExpectationOutcome& o = watcher.outcomes()[static_cast<std::size_t>(f)];
  r.passed = false;
  r.line = e.line;
  r.where = scene.file + ":" + std::to_string(e.line) + ": " + expectationText(e);
  r.message = o.probe.message + "\n" +
              (e.atEnd() ? std::string("in the finished render")
                         : "at the end of pass " + std::to_string(o.pass) + " " + quoted(o.passLabel));
  r.difference = o.difference;
  if (history) r.history = pixelHistory(scene, e.atEnd() ? watcher.passes() + 1 : o.pass, o.probe.x, o.probe.y);
  return r;
}

SceneTestResult runSceneTest(const Scene& scene, const std::function<void(const RenderProgress&)>& progress) {
  GLContext gl(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
  GLCommandStream stream(gl, false);
  SceneExpectationWatcher watcher(scene, stream, gl);
  renderScene(scene, stream, progress);
  watcher.finish();
  return sceneTestResult(scene, watcher, true);
}

std::string sceneFailureText(const SceneTestResult& r, const std::string& indent) {
  std::string text = r.message + "\n" + r.history;
  std::string o = indent;
  for (std::size_t i = 0; i < text.size(); ++i) {
    o += text[i];
    if (text[i] == '\n' && i + 1 < text.size()) o += indent;
  }
  return o;
}

}  // namespace mpr::cli
