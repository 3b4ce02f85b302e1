#pragma once
// The vertex the draw stage hands to set-up: clip coordinates and the
// varyings interpolated across the triangle (GL 1.1 section 2.13.8: colours
// and the fog coordinate are interpolated in clip space before the divide).
#include <array>

#include "util/vecmath.hpp"

namespace mpr {

inline constexpr int kVaryings = 9;  // front RGBA, back RGBA, fog

struct ClipVertex {
  Vec4 clip;                          // clip coordinates
  std::array<float, kVaryings> attr;  // interpolated linearly in clip space
};

// A plane a x + b y + c z + d w >= 0 in clip coordinates.
using ClipPlane = Vec4;

}  // namespace mpr
