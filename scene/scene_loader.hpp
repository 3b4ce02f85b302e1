#pragma once
// Scene files (YAML, docs/scene-format.md) to the scene model, with errors a
// person can act on: FILE:LINE:COLUMN, what was expected, and the closest key
// for a misspelled one.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"
#include "util/printable_text.hpp"

namespace mpr {

// The largest scene file read (a regular file only): 16 MiB; meshes live in
// their own files.
inline constexpr std::uint64_t kMaxSceneBytes = std::uint64_t{16} << 20;
// The most triangles a scene may hold, all objects together (aliases repeat
// an object for free in the file): 24 Mi, one 4096-division sphere or one
// 1024-division box and more.
inline constexpr std::uint64_t kMaxSceneTriangles = std::uint64_t{24} << 20;

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, int line, int column, const std::string& message)
      : std::runtime_error(printableText(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message)) {}
};

// Loads and validates a scene file. `overrides` are "key.path=value" pairs
// applied to the document before it is read (mpr render --set).
//
// Mesh paths are relative to the scene file's folder; absolute paths and
// paths through ".." are read as given, unless `confine` is set (mpr render
// --confine, for services that render scenes they did not write): then any
// mesh outside the scene's folder (after resolving links) is refused.
Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides = {}, bool confine = false);
// The same from text; `file` names it in messages and anchors relative mesh paths.
Scene loadSceneText(const std::string& text, const std::string& file, const std::vector<std::string>& overrides = {},
                    bool confine = false);

// The embedded default scene (a room with a mirror, a glass pane, a cube, a
// sphere and one light) as YAML text.
const std::string& defaultSceneText();

// A JSON Schema-like description of the format (mpr render --describe-format).
std::string describeSceneFormat();

}  // namespace mpr
