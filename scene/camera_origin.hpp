#pragma once
// Camera-relative coordinates (issue 43, defect 11): a scene far from the
// world's origin keeps its positions relative to a point near the camera,
// computed in double, so that the emulated float pipeline sees the same
// small numbers it sees when the scene lies at the origin. Real-time
// engines do the same (transforms composed in double on the CPU, relative
// to the camera); the GL calls stay ordinary calls Mesa replays.
#include "scene/scene.hpp"

namespace mpr {

// The loader keeps a scene's coordinates as written while its camera is
// within this distance (per axis) of the world's origin, where a float
// resolves 2^-14 (6e-5) or finer; farther out it places the origin at the
// camera before any position is rounded to a float (at 1e5 a float resolves
// only 2^-7, and a mirror 0.02 before a wall moves by a third of its gap).
inline constexpr double kFarFromOrigin = 1024.0;

// The origin the loader gives a scene whose camera the file puts at `eye`.
DVec3 loadingOrigin(DVec3 eye);

// The scene as the renderer draws it: its origin moved to its camera,
// which then stands at (0, 0, 0) (unchanged when it already does); every
// position re-expressed relative to it, each difference taken in double
// and rounded once. Directions (normals, up) do not change.
void moveOriginToCamera(Scene& s);

}  // namespace mpr
