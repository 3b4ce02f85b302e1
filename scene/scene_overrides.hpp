#pragma once
// mpr render --set key.path=value: a value placed in the scene's YAML
// document before it is read, and what the loader needs to place an error
// in what a --set gave or made at "--set key.path=value:1:1", never at a
// line of the file.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace mpr {

struct SceneOverride {
  std::string text;                 // "key.path=value" as given
  YAML::Node node;                  // the parsed value, placed in the document
  std::vector<YAML::Node> created;  // the mappings its path made on the way

  // Whether `at` is the value this --set gave or lies inside it (a key or a
  // value at any depth).
  bool gave(const YAML::Node& at) const;
  // Whether `at` is a mapping its path made on the way.
  bool made(const YAML::Node& at) const;
  // Whether the value it gave lies inside `root` (a section of the scene).
  bool inside(const YAML::Node& root) const;
};

// Places `kv` ("key.path=value") in `doc`: a mapping entered by key (made
// where missing), a list by index (objects.0.scale). A malformed `kv`, a
// value that is not YAML, or a path through a scalar or past a list's end
// throws SceneError at "--set ...:1:COLUMN".
SceneOverride applyOverride(YAML::Node& doc, const std::string& kv);

}  // namespace mpr
