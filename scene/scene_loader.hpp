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
// The counts that multiply a render's passes, refused at their key before
// anything is read from the list (YAML aliases repeat an entry for free in
// the file, so a 3 MB file can list a million lights). Every view draws one
// lit pass and one shadow pass per light, every object in every pass, and
// every expectation is read at its pass: 1 024 lights (the papers' scenes
// have one to eight; OpenGL lights eight at a time), 65 536 objects, 65 536
// expectations. Samples are bounded at their keys (1 024 images at most).
inline constexpr std::size_t kMaxSceneLights = 1024;
inline constexpr std::size_t kMaxSceneObjects = 65536;
inline constexpr std::size_t kMaxSceneExpectations = 65536;

// The narrowest camera.fov accepted, in degrees. Narrower, the projection
// maps the scene's off-axis vertices to clip coordinates so large (cot of
// half the view) that the clipper's float interpolation misplaces the
// vertices it makes on the window's edges by pixels: bands of the window are
// left empty. Measured on the default scene, the bands start at about 1e-6
// degrees per pixel of window height (between 1e-5 and 1.5e-5 at 12 pixels,
// 3e-4 and 5e-4 at 480, 1e-3 and 2e-3 at 1200, 0.01 and 0.02 at 16384, the
// tallest window): 0.05 keeps 2.5 times that at 16384.
inline constexpr double kMinFieldOfView = 0.05;

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, int line, int column, const std::string& message)
      : std::runtime_error(printableText(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message)) {}
};

// Loads and validates a scene file. `overrides` are "key.path=value" pairs
// applied to the document before it is read (mpr render --set); an error in
// what one of them gave or made is placed at "--set key.path=value:1:1".
// A file holds one YAML document (a second one is refused where it starts);
// a number or a boolean is a plain scalar (a quoted '45' is refused).
// Warnings (faces a mesh file's reader dropped) go to standard error as
// "FILE:LINE:COLUMN: warning: ...", once the scene has loaded.
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
