#pragma once
// The values of a scene file read from its YAML nodes, each checked as it is
// read, and every error placed where the value came from: FILE:LINE:COLUMN
// in the file, or the --set that gave or made it. The section readers
// (scene/scene_section_readers.hpp) read through one of these.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_format.hpp"
#include "scene/scene_overrides.hpp"

namespace mpr {

class SceneNodeReader {
 public:
  SceneNodeReader(std::string file, std::vector<SceneOverride> overrides)
      : file_(std::move(file)), overrides_(std::move(overrides)) {}

  // The scene file's name, as messages give it; relative mesh paths start at its folder.
  const std::string& file() const { return file_; }

  // Throws SceneError at `at`: its place in the file, or the --set it came from.
  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const;
  // A warning, placed as fail places an error; loadSceneText writes them
  // once the scene has loaded.
  void warn(const YAML::Node& at, const std::string& message) const;
  const std::vector<std::string>& warnings() const { return warnings_; }
  // Whether a --set gave `at` (it has no line in the file).
  bool givenBySet(const YAML::Node& at) const;
  // Whether a --set gave anything inside `root` (a section of the scene).
  bool setInside(const YAML::Node& root) const;

  // `map` is a mapping of the section's keys, each given once; an unknown
  // key is refused with the closest known one.
  void checkKeys(const YAML::Node& map, const std::vector<scene_format::KeySpec>& keys, const std::string& where) const;
  void checkUniqueKeys(const YAML::Node& map, const std::string& where) const;
  // A list whose entries multiply the render's work, bounded before any is read.
  void checkCount(const YAML::Node& list, const std::string& key, std::size_t max) const;

  // A finite number in a float's range, written as a plain scalar.
  double number(const YAML::Node& n, const std::string& what) const;
  // The same in [lo, hi] ((lo, hi] with openLo).
  double number(const YAML::Node& n, const std::string& what, double lo, double hi, bool openLo = false) const;
  int integer(const YAML::Node& n, const std::string& what, long lo, long hi) const;
  bool boolean(const YAML::Node& n, const std::string& what) const;
  std::string string(const YAML::Node& n, const std::string& what) const;
  Vec3 vec3(const YAML::Node& n, const std::string& what) const;
  // A position as written, in double: kept so until it is made relative to
  // the scene's origin (scene/camera_origin.hpp).
  DVec3 dvec3(const YAML::Node& n, const std::string& what) const;
  Vec3 rgb(const YAML::Node& n, const std::string& what) const;  // a vec3 >= 0

 private:
  void checkPlain(const YAML::Node& n, const std::string& what, const std::string& kind) const;

  std::string file_;
  std::vector<SceneOverride> overrides_;
  mutable std::vector<std::string> warnings_;
};

}  // namespace mpr
