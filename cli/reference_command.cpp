#include "cli/reference_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/output_set.hpp"
#include "cli/scene_arguments.hpp"
#include "cli/scene_limits.hpp"
#include "reference/reference_image.hpp"
#include "reference/reference_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "util/number_text.hpp"

namespace mpr::cli {
namespace {

struct ReferenceCommandOptions {
  std::string scene;
  std::string output = "out/reference.png";
  int width = 0, height = 0;
  TracerOptions tracer;
  std::vector<std::string> sets;
  SceneLimits limits;  // --confine only: the tracer makes no passes (--spp and --bounces bound it)
};

int runReference(const ReferenceCommandOptions& o) {
  Scene scene;
  try {
    scene = loadCommandScene(o.scene, o.sets, o.width, o.height, {}, o.limits.confine);
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (const std::string problem = imageOutputProblem("reference", o.output); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  OutputSet outputs("reference");
  outputs.addSceneInputs(scene);
  outputs.addFile("-o", o.output);
  if (const std::string problem = outputs.problem(); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  ReferenceOptions options;
  options.samplesPerPixel = o.tracer.spp;
  options.bounces = o.tracer.bounces;
  options.threads = o.tracer.threads;
  options.model = o.tracer.model == "physical" ? ShadingModel::Physical : ShadingModel::Pipeline;
  const bool tty = isatty(2);
  const auto t0 = std::chrono::steady_clock::now();
  if (tty)
    options.progress = [&](int rows, int total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double eta = rows > 0 ? s * (total - rows) / rows : 0.0;
      std::cerr << "\rreference: row " << rows << " of " << total << ", ETA " << fixedText(eta, 1) << " s   " << std::flush;
    };
  const ReferenceImage image = renderReference(scene, options);
  if (tty) std::cerr << "\r" << std::string(60, ' ') << "\r";
  try {
    writeReferenceImage(image, outputs.open(o.output));
    outputs.commit();
  } catch (const std::exception& e) {
    std::cerr << "mpr reference: " << e.what() << "\n";
    return 1;
  }
  const ReferenceStats& s = image.stats;
  const double rays = static_cast<double>(s.cameraRays + s.specularRays + s.shadowRays);
  std::cerr << "traced " << scene.file << " (" << image.width << "x" << image.height << ", " << o.tracer.spp << " spp, "
            << o.tracer.model << ") to " << o.output << " in " << fixedText(s.seconds, 2) << " s ("
            << fixedText(s.seconds > 0.0 ? rays / s.seconds / 1e6 : 0.0, 2) << " M rays/s)\n";
  return 0;
}

}  // namespace

void addReferenceCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ReferenceCommandOptions>();
  CLI::App* c = app.add_subcommand("reference", "Trace a scene with the reference ray tracer (default: the default scene)");
  c->footer(
      "A Whitted ray tracer over the scene model (not over GL calls): exact shadows, area lights,\n"
      "mirrors, refraction and the light they pass on. The render switches and recursion_depth of the\n"
      "scene are the pipeline's and are ignored. The bytes do not depend on --threads.\n"
      "Scene errors print FILE:LINE:COLUMN, exit with status 2 and write nothing.");
  c->add_option("scene", o->scene, "scene file (YAML); none traces the default scene");
  c->add_option("-o,--output", o->output, "output image: .png, .tif, .tiff (8-bit) or .exr (linear float)");
  addTracerOptions(*c, o->tracer);
  c->add_option("--width", o->width, "image width (overrides render.width)")->check(CLI::Range(1, 16384));
  c->add_option("--height", o->height, "image height (overrides render.height)")->check(CLI::Range(1, 16384));
  c->add_option("--set", o->sets, "override a scene value: key.path=value (repeatable)");
  addConfineOption(*c, o->limits);
  c->callback([o, &exitCode] { exitCode = runReference(*o); });
}

}  // namespace mpr::cli
