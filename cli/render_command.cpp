#include "cli/render_command.hpp"

#include <unistd.h>

#include <chrono>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/scene_expectations.hpp"
#include "algorithms/scene_renderer.hpp"
#include "cli/output_set.hpp"
#include "cli/scene_arguments.hpp"
#include "cli/scene_limits.hpp"
#include "cli/scene_test.hpp"
#include "cli/thread_option.hpp"
#include "framebuffer/image_writer.hpp"
#include "framebuffer/npy_writer.hpp"
#include "util/saturating.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::cli {
namespace {

// A JSON string literal: quotes, backslashes and control characters escaped
// (a scene path may hold any of them).
std::string jsonString(const std::string& s) {
  std::string o = "\"";
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') o += '\\', o += ch;
    else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      o += buf;
    } else o += ch;
  }
  return o + "\"";
}

struct RenderOptions {
  std::string scene;
  std::string output = "out/render.png";
  int width = 0, height = 0;
  std::vector<std::string> sets;
  std::string dumpDir, traceFile, statsFile;
  bool dumpGiven = false, traceGiven = false, statsGiven = false;  // --dump '' is an error, not "none"
  bool describe = false;
  bool noCull = false;
  int threads = 1;
  SceneLimits limits;
};

std::string statsJson(const GLCommandStream& s, const Scene& scene, const RenderResult& r, double seconds) {
  std::ostringstream o;
  const PipelineCounters& c = s.counters();
  o << "{\n  \"scene\": " << jsonString(scene.file) << ",\n  \"width\": " << scene.render.width << ",\n  \"height\": "
    << scene.render.height << ",\n  \"seconds\": " << seconds << ",\n  \"gl_calls\": " << s.calls()
    << ",\n  \"gl_errors\": " << s.glErrors() << ",\n  \"scene_triangles\": " << scene.triangleCount()
    << ",\n  \"triangles\": " << c.triangles << ",\n  \"fragments_tested\": " << c.fragmentsTested
    << ",\n  \"fragments_written\": " << c.fragmentsWritten;
  // The recursion's own counts beside the planner's predictions (mpr info).
  o << ",\n  \"views\": " << r.counts.views << ",\n  \"predicted_views\": " << r.plan.predictedViews()
    << ",\n  \"views_per_level\": [";
  for (std::size_t l = 0; l < r.counts.viewsAtLevel.size(); ++l) o << (l ? ", " : "") << r.counts.viewsAtLevel[l];
  o << "],\n  \"light_passes\": " << r.counts.lightPasses << ",\n  \"predicted_light_passes\": "
    << r.plan.predictedLightPasses() << ",\n  \"shadow_passes\": " << r.counts.shadowPasses
    << ",\n  \"predicted_shadow_passes\": " << r.plan.predictedShadowPasses()
    << ",\n  \"faces_culled\": " << r.counts.facesSkipped << ",\n  \"zfail_volumes\": " << r.counts.zfailVolumes
    << ",\n  \"passes\": {";
  bool first = true;
  for (const auto& [kind, p] : s.passStatistics()) {
    o << (first ? "\n" : ",\n") << "    " << jsonString(kind) << ": {\"count\": " << p.passes << ", \"gl_calls\": " << p.calls
      << ", \"triangles\": " << p.triangles << ", \"fragments_tested\": " << p.fragmentsTested
      << ", \"fragments_written\": " << p.fragmentsWritten << ", \"seconds\": " << p.seconds << "}";
    first = false;
  }
  o << "\n  }\n}\n";
  return o.str();
}

int runRender(const RenderOptions& o) {
  if (o.describe) {
    std::cout << describeSceneFormat();
    return 0;
  }
  Scene scene;
  try {
    scene = loadCommandScene(o.scene, o.sets, o.width, o.height, {}, o.limits.confine);
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (const std::string problem = imageOutputProblem("render", o.output); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  // Every output is checked before the render and written after it, together.
  OutputSet outputs("render");
  outputs.addSceneInputs(scene);
  outputs.addFile("-o", o.output);
  if (o.dumpGiven) outputs.addFolder("--dump", o.dumpDir, npyDumpFileNames());
  if (o.traceGiven) outputs.addFile("--trace", o.traceFile);
  if (o.statsGiven) outputs.addFile("--stats", o.statsFile);
  if (const std::string problem = outputs.problem(); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  // The plan's counts are exact with culling off and an upper bound with it:
  // a plan past --max-passes is refused before it starts without culling, and
  // a culled render is stopped when its views alone pass the limit.
  const RenderPlan plan = planRender(scene, !o.noCull);
  if (const std::string problem = planLimitProblem(scene, plan, !o.noCull, o.limits); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  std::unique_ptr<GLContext> gl;
  try {
    gl = std::make_unique<GLContext>(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
  } catch (const FramebufferSizeError& e) {
    std::cerr << scene.file << ": " << e.what() << "\n";
    return 2;
  }
  gl->setThreads(o.threads);
  GLCommandStream stream(*gl, o.traceGiven);
  // The scene's expect: list, read at its passes (nothing drawn changes).
  SceneExpectationWatcher watcher(scene, stream, *gl);
  const bool tty = isatty(2);
  const auto t0 = std::chrono::steady_clock::now();
  RenderResult result;
  try {
    result = renderScene(scene, stream, passLimitWatch(o.limits, [&](const RenderProgress& p) {
      if (tty) std::cerr << "\rrender: view " << p.views << " of at most " << countText(p.predictedViews) << "   " << std::flush;
    }), !o.noCull);
  } catch (const PassLimitReached& stop) {
    if (tty) std::cerr << "\r" << std::string(60, ' ') << "\r";
    std::cerr << passLimitMessage(scene, stop, o.limits) << "; nothing was written\n";
    return 2;
  }
  watcher.finish();
  for (const std::string& w : result.counts.warnings) std::cerr << scene.file << ": warning: " << w << "\n";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (tty) std::cerr << "\r" << std::string(60, ' ') << "\r";
  try {
    writeColorImage(gl->framebuffer(), outputs.open(o.output));
    if (o.dumpGiven)
      for (const NamedBytes& nb : framebufferNpyDumps(gl->framebuffer()))
        outputs.write((std::filesystem::path(o.dumpDir) / (nb.name + ".npy")).string(), nb.bytes);
    if (o.traceGiven) outputs.write(o.traceFile, stream.trace());
    if (o.statsGiven) outputs.write(o.statsFile, statsJson(stream, scene, result, seconds));
    outputs.commit();
  } catch (const std::exception& e) {
    std::cerr << "mpr render: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "rendered " << scene.file << " (" << scene.render.width << "x" << scene.render.height << ", "
            << scene.triangleCount() << " triangles) to " << o.output << " in " << seconds << " s\n";
  // The expectations, once the render's files are written (they never change
  // what is drawn): a located error for an `after` no pass matched (status
  // 2), else the first that does not hold, in the render's order (status 1).
  if (scene.expectations.empty()) return 0;
  const cli::SceneTestResult t = cli::sceneTestResult(scene, watcher, true);
  for (const std::string& e : t.errors) std::cerr << e << "\n";
  if (!t.errors.empty()) return 2;
  if (!t.passed) {
    std::cerr << t.where << "\n" << cli::sceneFailureText(t, "  ");
    return 1;
  }
  std::cerr << t.expectations << " expectation" << (t.expectations == 1 ? "" : "s") << " held\n";
  return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* c = app.add_subcommand("render", "Render a scene file (default: the embedded default scene)");
  c->footer(
      "The scene format is docs/reference/scene-format.md (mpr render --describe-format prints its schema).\n"
      "Scene errors print FILE:LINE:COLUMN, exit with status 2 and write nothing. The image is written\n"
      "through OpenImageIO (PNG, TIFF or EXR by extension) to a temporary name and renamed into place.\n"
      "The scene's expect: list (probes read after a pass whose label matches, or at the end) is checked\n"
      "once the files are written: the first expectation that does not hold, in the render's order,\n"
      "prints FILE:LINE: the expectation, expected and found, the pass and the pixel's history, and\n"
      "exits with status 1; an after: that matched no pass is a located error, status 2.");
  c->add_option("scene", o->scene, "scene file (YAML); none renders the default scene");
  c->add_option("-o,--output", o->output, "output image (default out/render.png)");
  c->add_option("--width", o->width, "image width (overrides render.width)")->check(CLI::Range(1, 16384));
  c->add_option("--height", o->height, "image height (overrides render.height)")->check(CLI::Range(1, 16384));
  c->add_option("--set", o->sets, "override a scene value: key.path=value (repeatable)");
  auto dump = c->add_option("--dump", o->dumpDir, "also write the final buffers as .npy files into this folder");
  auto trace = c->add_option("--trace", o->traceFile, "write the GL calls executed as a GL script (.gls)");
  auto stats =
      c->add_option("--stats", o->statsFile, "write statistics as JSON: passes by kind, calls, triangles, fragments, time");
  addSceneLimitOptions(*c, o->limits);
  addThreadsOption(*c, o->threads);
  c->add_flag("--no-cull", o->noCull, "recurse into every mirror face, even those seen from behind or hidden");
  c->add_flag("--describe-format", o->describe, "print a JSON Schema-like description of the scene format");
  c->callback([o, dump, trace, stats, &exitCode] {
    o->dumpGiven = dump->count() > 0, o->traceGiven = trace->count() > 0, o->statsGiven = stats->count() > 0;
    exitCode = runRender(*o);
  });
}

}  // namespace mpr::cli
