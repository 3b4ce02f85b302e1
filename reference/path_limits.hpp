#pragma once
// Limits the reference's light paths share (the ray tracer and the light
// paths through mirrors and glass): one value each, in one place.

namespace mpr {

// A specular path stops where its weight falls below 1/512: half of the
// last step of an 8-bit channel, so what it leaves out cannot change a
// pixel by more than rounding.
inline constexpr double kMinPathWeight = 1.0 / 512.0;
// Secondary rays and shadow segments start (and stop) this far from the
// surfaces they leave (scene units): the points lie on triangles, and the
// scene's coordinates are floats (~1e-7 relative).
inline constexpr double kSurfaceEpsilon = 1e-6;

}  // namespace mpr
