#include "cli/step_command.hpp"

#include <chrono>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/scene_renderer.hpp"
#include "stepper/script_passes.hpp"
#include "cli/scene_limits.hpp"
#include "cli/thread_option.hpp"
#include "cli/step_page.hpp"
#include "script/gl_script_runner.hpp"
#include "stepper/gl_state_json.hpp"
#include "stepper/pixel_history.hpp"
#include "stepper/pixel_history_text.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::cli {
namespace {

struct StepOptions {
  std::string input;
  std::string pixel;
  int state = -1;
  std::string html;
  bool htmlGiven = false;  // --html "" is an error, not "no page"
  bool pixelGiven = false;  // and so is --pixel ""
  int historyMb = 64;
  int threads = 1;
  SceneLimits limits;  // a scene's: its meshes and the passes of its render
};

// A script, or the trace of a scene's render read back as one.
// A render past --max-passes throws PassLimitMessage.
struct PassLimitMessage {
  std::string text;
};

Script loadInput(const std::string& path, bool progress, const SceneLimits& limits, int threads) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".yaml" && ext != ".yml") return loadScript(path);
  const Scene scene = loadSceneFile(path, {}, limits.confine);
  if (progress) std::cerr << "mpr step: rendering " << path << " for its GL calls\n";
  GLContext gl(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
  gl.setThreads(threads);
  GLCommandStream stream(gl, true);
  try {
    renderScene(scene, stream, passLimitWatch(limits));
  } catch (const PassLimitReached& stop) {
    throw PassLimitMessage{passLimitMessage(scene, stop, limits)};
  }
  return parseScript(stream.trace(), path + " (its render's GL calls)");
}

int runStep(const StepOptions& o) {
  const auto started = std::chrono::steady_clock::now();
  Script script;
  try {
    script = loadInput(o.input, o.htmlGiven, o.limits, o.threads);
  } catch (const PassLimitMessage& e) {
    std::cerr << e.text << "\n";
    return 2;
  } catch (const ScriptError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  const auto profile = findProfile(script.profile.value_or("indigo"));
  if (!profile) {
    std::cerr << "mpr step: unknown profile '" << *script.profile << "' (known: indigo, mesa)\n";
    return 2;
  }
  if (o.htmlGiven) {
    if (o.historyMb < 0) {
      std::cerr << "mpr step: --history-mb must be 0 or more, not " << o.historyMb << "\n";
      return 2;
    }
    return writeStepPage(script, *profile, {o.html, o.input, static_cast<std::size_t>(o.historyMb) << 20, started});
  }
  int px = -1, py = -1;
  if (o.pixelGiven) {
    char extra = 0;
    if (std::sscanf(o.pixel.c_str(), "%d,%d%c", &px, &py, &extra) != 2 || px < 0 || py < 0 || px >= script.width ||
        py >= script.height) {
      std::cerr << "mpr step: --pixel must be X,Y inside the " << script.width << "x" << script.height
                << " window (origin bottom-left), not '" << o.pixel << "'\n";
      return 2;
    }
  }
  const std::vector<ScriptPass> passes = scriptPasses(script);
  if (o.state >= static_cast<int>(passes.size())) {
    std::cerr << "mpr step: --state " << o.state << " is past the last pass (" << passes.size() - 1 << ")\n";
    return 2;
  }
  std::unique_ptr<GLContext> context;
  try {
    context = std::make_unique<GLContext>(script.width, script.height, *profile);
  } catch (const FramebufferSizeError& e) {
    std::cerr << script.file << ": " << e.what() << "\n";
    return 2;
  }
  context->setThreads(o.threads);  // --pixel observes fragments: each triangle then on one thread
  GLContext& gl = *context;
  if (px >= 0) {
    const std::string history = recordPixelHistory(script, gl, px, py);
    std::cout << "pixel (" << px << "," << py << ") of " << script.file << "\n"
              << history << "final: "
              << pixelValueText(gl.stencilAt(px, py), profile->stencilBits, gl.depthAt(px, py), gl.colorAt(px, py))
              << "\n";
    return 0;
  }

  int pass = 0;
  std::optional<std::string> stateAtEnd;
  ScriptHooks hooks;
  hooks.onPass = [&](const ScriptCommand&) {
    if (pass == o.state) stateAtEnd = glStateJson(gl);
    ++pass;
  };
  runScript(script, gl, hooks);
  if (pass == o.state) stateAtEnd = glStateJson(gl);

  if (o.state >= 0) {
    std::cout << *stateAtEnd;
    return 0;
  }
  for (std::size_t i = 0; i < passes.size(); ++i)
    std::cout << "pass " << i << " (line " << passes[i].line << "): " << passes[i].label << "\n";
  return 0;
}

}  // namespace

void addStepCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<StepOptions>();
  CLI::App* c = app.add_subcommand("step", "Walk a GL script (or a scene's GL calls) pass by pass");
  c->footer(
      "With no option: the list of passes (pass 0 is what comes before the first @pass).\n"
      "--pixel X,Y (window coordinates, origin bottom-left): every fragment that reached the pixel,\n"
      "pass by pass, with the stencil and depth tests and the operation applied, and every clear or\n"
      "accumulation return that changed it; then its final stencil in decimal, hex and binary.\n"
      "--state N: the GL state at the end of pass N, as JSON.\n"
      "--html DIR: a static page to open in a browser (DIR/index.html, no server needed): the pass\n"
      "tree (step with the arrow keys or j/k), each pass's GL state and pseudo-code line, its colour,\n"
      "depth, stencil (false colour with the algorithm's values named, or one bit) and accumulation\n"
      "buffers before and after it, and a click on a pixel shows the --pixel history up to that pass.\n"
      "DIR must be new, empty, or an earlier page (replaced whole; a failed run leaves it as it was).\n"
      "Every pixel's history is recorded, compressed, up to --history-mb megabytes; past that, up to\n"
      "the pass where the limit was reached, and the page gives the --pixel command for the rest.");
  c->add_option("input", o->input, "a GL script (.gls) or a scene (.yaml)")->required();
  auto pixel = c->add_option("--pixel", o->pixel, "X,Y: the pixel's history");
  auto state = c->add_option("--state", o->state, "N: the GL state at the end of pass N, as JSON")
                   ->check(CLI::Range(0, std::numeric_limits<int>::max()))
                   ->excludes(pixel);
  auto html = c->add_option("--html", o->html, "DIR: write the stepper page there")->excludes(pixel)->excludes(state);
  c->add_option("--history-mb", o->historyMb, "with --html: the most megabytes of compressed pixel history (default 64)")
      ->needs(html)
      ->check(CLI::Range(0, 1 << 20));
  addSceneLimitOptions(*c, o->limits);
  addThreadsOption(*c, o->threads);
  c->callback([o, html, pixel, &exitCode] {
    o->htmlGiven = html->count() > 0;
    o->pixelGiven = pixel->count() > 0;
    exitCode = runStep(*o);
  });
}

}  // namespace mpr::cli
