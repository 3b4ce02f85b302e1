#include "cli/scene_arguments.hpp"

#include <filesystem>

#include "scene/scene_loader.hpp"

namespace mpr::cli {

std::vector<std::string> commandSets(const std::vector<std::string>& sets, int width, int height) {
  std::vector<std::string> s = sets;
  if (width > 0) s.push_back("render.width=" + std::to_string(width));
  if (height > 0) s.push_back("render.height=" + std::to_string(height));
  return s;
}

Scene loadCommandScene(const std::string& file, const std::vector<std::string>& sets, int width, int height,
                       const std::vector<std::string>& more, bool confine) {
  std::vector<std::string> s = commandSets(sets, width, height);
  s.insert(s.end(), more.begin(), more.end());
  return file.empty() ? loadSceneText(defaultSceneText(), "<default scene>", s) : loadSceneFile(file, s, confine);
}

std::string imageOutputProblem(const std::string& command, const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr") return "";
  return "mpr " + command + ": output '" + path + "' must end in .png, .tif, .tiff or .exr";
}

void addTracerOptions(CLI::App& command, TracerOptions& o) {
  command.add_option("--spp", o.spp, "reference samples per pixel, stratified (default 16)")->check(CLI::Range(1, 65536));
  command
      .add_option("--model", o.model,
                  "reference local model: pipeline (GL 1.x lighting, default) or physical (Ward's eq. 5 where roughness "
                  "is given)")
      ->check(CLI::IsMember({"pipeline", "physical"}));
  command
      .add_option("--bounces", o.bounces,
                  "specular faces a reference path may pass (default: until its weight is below 1/512)")
      ->check(CLI::Range(-1, 100));
  command.add_option("--threads", o.threads, "reference tracer threads (default: every hardware thread)")
      ->check(CLI::Range(0, 1024));
}

}  // namespace mpr::cli
