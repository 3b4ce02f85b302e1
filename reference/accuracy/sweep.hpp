#pragma once
// What `mpr accuracy` renders: settings of scene keys, one key at a time
// around the scene's own values (the 1997 paper's Tables 2 and 3 vary one
// setting a row), or the full product of the values asked for.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.hpp"

namespace mpr {

// One `--vary KEY=V1,V2,...`.
struct VaryKey {
  std::string key;
  std::vector<std::string> values;
};

// Throws std::invalid_argument with a message naming the argument.
VaryKey parseVary(const std::string& argument);

// With no --vary: recursion depth 0..3, shadow recursion depth 0..2, shadows
// on and off, the three placements of the refraction map, lit faces
// tessellated to edges of 1, 0.5 and 0.25, and 4 and 16 antialias and
// light samples.
std::vector<VaryKey> defaultSweep();

// One rendering: the scene with these key=value overrides.
struct SweepSetting {
  std::vector<std::pair<std::string, std::string>> overrides;
  std::vector<std::string> sets() const;  // "key=value", for the scene loader
  std::string label() const;               // "render.recursion_depth=3", or "scene" without overrides
};

// One key at a time: first the scene as it is, then each value of each key
// (`product`: every combination instead). Settings that load to the same
// scene as an earlier one are left out, so a value equal to the scene's own
// is not rendered twice (`sameScene` decides).
std::vector<SweepSetting> expandSweep(const std::vector<VaryKey>& keys, bool product);

// The single-pass baseline: every multi-pass effect off (no shadow volumes,
// no mirror or refraction recursion, no translucency or frosted passes, one
// image: no antialiasing, depth of field or soft shadows).
std::vector<std::string> singlePassSets();

// A description of everything that changes a rendering, so that two
// settings can be recognised as the same scene.
std::string sceneFingerprint(const Scene& scene);

// The value a key has in `scene`, as text, for the render.* keys and the
// camera's; nothing for keys it does not know.
std::optional<std::string> sceneValue(const Scene& scene, const std::string& key);

}  // namespace mpr
