#pragma once
// Scene files (YAML, docs/scene-format.md) to the scene model, with errors a
// person can act on: FILE:LINE:COLUMN, what was expected, and the closest key
// for a misspelled one.
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"

namespace mpr {

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, int line, int column, const std::string& message)
      : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message) {}
};

// Loads and validates a scene file. `overrides` are "key.path=value" pairs
// applied to the document before it is read (mpr render --set).
Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from text; `file` names it in messages and anchors relative mesh paths.
Scene loadSceneText(const std::string& text, const std::string& file, const std::vector<std::string>& overrides = {});

// The embedded default scene (a room with a mirror, a glass pane, a cube, a
// sphere and one light) as YAML text.
const std::string& defaultSceneText();

// A JSON Schema-like description of the format (mpr render --describe-format).
std::string describeSceneFormat();

}  // namespace mpr
