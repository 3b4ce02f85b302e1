#include "cli/step_page.hpp"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "algorithms/stencil_levels.hpp"
#include "cli/frame_delta_encoder.hpp"
#include "cli/page_encoding.hpp"
#include "cli/page_folder.hpp"
#include "cli/pixel_history_encoder.hpp"
#include "stepper/script_passes.hpp"
#include "cli/web_assets.hpp"
#include "script/gl_script_runner.hpp"
#include "stepper/gl_state_json.hpp"
#include "stepper/pixel_history_text.hpp"

namespace mpr::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Square tiles of pixel histories: a click decompresses one tile, not the frame.
constexpr int kHistoryTile = 32;

std::string packed(std::string_view raw) { return base64(zlibCompress(raw)); }

std::string megabytes(std::size_t bytes) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MB";
  return o.str();
}

// The input as a shell word, for the `mpr step --pixel` hint.
std::string shellWord(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./+:,") ==
                        std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// A JavaScript array of strings, one a line.
std::string stringArray(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += i ? ",\n" : "\n";
    out += jsString(items[i]);
  }
  out += "]";
  return out;
}

}  // namespace

int writeStepPage(const Script& script, const HardwareProfile& profile, const StepPageOptions& o) {
  if (const std::string problem = pageFolderProblem(o.dir, kStepPageGenerator); !problem.empty()) {
    std::cerr << "mpr step: --html: " << problem << "\n";
    return 2;
  }
  const Clock::time_point start = o.started;
  const std::vector<ScriptPass> passes = scriptPasses(script);
  std::unique_ptr<GLContext> context;
  try {
    context = std::make_unique<GLContext>(script.width, script.height, profile);
  } catch (const FramebufferSizeError& e) {
    std::cerr << script.file << ": " << e.what() << "\n";
    return 2;
  }
  GLContext& gl = *context;

  FrameDeltaEncoder frameDeltas(script.width, script.height);
  PixelHistoryEncoder history(script.width, script.height, kHistoryTile, o.historyBudgetBytes);
  std::vector<std::string> frames = {packed(frameDeltas.encode(gl.framebuffer()))};  // the buffers before any call
  std::vector<std::string> states;
  std::vector<std::vector<std::string>> errors(passes.size());
  std::size_t frameBytes = frames.front().size();

  PixelEventRecorder recorder(gl, gl.framebuffer().bounds(),
                              [&](const PixelEvent& e, const FragmentState& s) { history.add(e, s); });
  Clock::time_point lastReport = start;
  auto passEnded = [&](int pass) {
    states.push_back(glStateJson(gl));
    frames.push_back(packed(frameDeltas.encode(gl.framebuffer())));
    frameBytes += frames.back().size();
    history.passEnded(pass);
    const Clock::time_point now = Clock::now();
    if (now - lastReport > std::chrono::seconds(1)) {
      lastReport = now;
      std::cerr << "mpr step: recorded pass " << pass << " of " << passes.size() - 1 << " (" << std::fixed
                << std::setprecision(1) << std::chrono::duration<double>(now - start).count() << " s, "
                << history.eventCount() << " pixel events)\n";
    }
  };
  ScriptHooks hooks;
  hooks.beforeCall = [&](const ScriptCommand& c) { recorder.beforeCall(c); };
  hooks.onPass = [&](const ScriptCommand&) {
    recorder.startPass();
    passEnded(recorder.pass() - 1);
  };
  hooks.onGLError = [&](const ScriptCommand& c, std::uint32_t e) {
    errors[static_cast<std::size_t>(recorder.pass())].push_back(glErrorReport(c, e));
  };
  runScript(script, gl, hooks);
  recorder.finish();
  passEnded(recorder.pass());

  history.finish();
  // The histories: per tile, its chunks.
  std::string tilesJs = "[";
  std::size_t historyBytes = 0;
  for (int t = 0; t < history.tileCount(); ++t) {
    std::vector<std::string> chunks;
    for (const std::string& c : history.tileChunks(t % history.tilesAcross(), t / history.tilesAcross())) {
      chunks.push_back(base64(c));
      historyBytes += chunks.back().size();
    }
    tilesJs += t ? ",\n" : "\n";
    tilesJs += stringArray(chunks);
  }
  tilesJs += "]";
  const int recordedPasses = history.stopped() ? history.recordedPasses() : static_cast<int>(passes.size());

  // Written with streams: GCC 12 warns falsely (-Wrestrict) on long operator+ chains.
  const StencilLevels levels = stencilLevelsFor(profile);
  std::ostringstream meta;
  meta << "// Written by mpr step --html: the passes of " << jsString(o.input) << ", read by stepper.js.\n"
       << "window.MPR_STEP = {\n\"format\": 1,\n\"input\": " << jsString(o.input) << ",\n"
       << "\"width\": " << script.width << ", \"height\": " << script.height << ",\n"
       << "\"profile\": {\"name\": " << jsString(profile.name) << ", \"stencil_bits\": " << profile.stencilBits
       << ", \"depth_bits\": " << profile.depthBits << ", \"accum_has_alpha\": " << (profile.accumHasAlpha ? "true" : "false")
       << "},\n"
       << "\"levels\": {\"zero\": " << levels.zero << ", \"shad_min\": " << levels.shadMin << ", \"shad_zero\": "
       << levels.shadZero << ", \"max\": " << levels.max << "},\n"
       << "\"pixel_command\": " << jsString("mpr step " + shellWord(o.input) + " --pixel") << ",\n"
       << "\"history\": {\"tile\": " << kHistoryTile << ", \"recorded_passes\": " << recordedPasses
       << ", \"events\": " << history.eventCount() << ", \"limit_mb\": " << (o.historyBudgetBytes >> 20)
       << ",\n\"templates\": " << stringArray(history.templates()) << "},\n\"passes\": [";
  for (std::size_t p = 0; p < passes.size(); ++p)
    meta << (p ? ",\n" : "\n") << "{\"label\": " << jsString(passes[p].label) << ", \"line\": " << passes[p].line
         << ", \"header\": " << jsString(passHeaderLine(static_cast<int>(p), passes[p].label))
         << ", \"errors\": " << stringArray(errors[p]) << ",\n \"state\": " << jsString(states[p]) << "}";
  meta << "]\n};\n";

  std::ostringstream framesJs;
  framesJs << "// The buffers: before any call, then at each pass end, as zlib'd deltas (base64).\n"
           << "window.MPR_STEP.frames = " << stringArray(frames) << ";\n";
  std::ostringstream historyJs;
  historyJs << "// Every pixel's history, in " << kHistoryTile << "-pixel tiles, each a list of zlib chunks (base64).\n"
            << "window.MPR_STEP.history.tiles = " << tilesJs << ";\n";

  std::vector<PageFile> files;
  for (const auto& [name, text] : webAssets()) files.emplace_back(std::string(name), std::string(text));
  files.emplace_back("passes.js", meta.str());
  files.emplace_back("frames.js", framesJs.str());
  files.emplace_back("history.js", historyJs.str());
  std::size_t total = 0;
  for (const PageFile& f : files) total += f.second.size();
  try {
    writePageFolder(o.dir, kStepPageGenerator, files);
  } catch (const std::exception& e) {
    // A failure while writing (a full disk) is status 1, as for every output.
    std::cerr << "mpr step: --html: " << e.what() << "\n";
    return 1;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::cout << o.dir << "/index.html: " << passes.size() << " passes, " << megabytes(total) << " (buffers "
            << megabytes(frameBytes) << ", pixel histories " << megabytes(historyBytes) << ", "
            << history.eventCount() << " pixel events";
  if (history.stopped())
    std::cout << ", recorded for passes 0 to " << recordedPasses - 1 << " only: over the " << (o.historyBudgetBytes >> 20)
              << " MB limit";
  std::cout << ") in " << std::fixed << std::setprecision(2) << seconds << " s\n";
  return 0;
}

}  // namespace mpr::cli
