#pragma once
// What `render`, `reference` and `accuracy` share: the scene they work on
// and the image files they accept.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace mpr::cli {

// The scene file (none: the embedded default scene) with the --set
// overrides, then --width and --height where given (> 0), and `more`.
// Throws SceneError (FILE:LINE:COLUMN) as the loader does. `confine`: mesh
// files only from inside the scene's folder (--confine).
Scene loadCommandScene(const std::string& file, const std::vector<std::string>& sets, int width, int height,
                       const std::vector<std::string>& more = {}, bool confine = false);

// The --set list the above applies before `more`.
std::vector<std::string> commandSets(const std::vector<std::string>& sets, int width, int height);

// Why `command` cannot write an image to `path`, or empty: the format
// follows the extension, .png, .tif, .tiff or .exr.
std::string imageOutputProblem(const std::string& command, const std::string& path);

// The reference tracer's options, for `reference` and `accuracy` (which
// traces its reference the same way): --spp, --model, --bounces and
// --threads, each with its range, checked before any work.
struct TracerOptions {
  int spp = 16, bounces = -1, threads = 0;
  std::string model = "pipeline";
};
void addTracerOptions(CLI::App& command, TracerOptions& o);

}  // namespace mpr::cli
