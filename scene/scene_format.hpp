#pragma once
// The scene format (docs/scene-format.md), one table per section: the single
// source of truth for the loader's unknown-key check, its suggestions and
// --describe-format (describeSceneFormat in scene/scene_loader.hpp).
#include <string_view>
#include <vector>

namespace mpr::scene_format {

// A key a section accepts: its name, the type and meaning --describe-format shows.
struct KeySpec {
  std::string_view key, type, meaning;
};

extern const std::vector<KeySpec> kTopKeys;       // the document's own keys
extern const std::vector<KeySpec> kCameraKeys;    // camera:
extern const std::vector<KeySpec> kLightKeys;     // each of lights:
extern const std::vector<KeySpec> kMaterialKeys;  // each of materials:
extern const std::vector<KeySpec> kObjectKeys;    // each of objects:
extern const std::vector<KeySpec> kRenderKeys;    // render:
extern const std::vector<KeySpec> kExpectKeys;    // each of expect:

}  // namespace mpr::scene_format
