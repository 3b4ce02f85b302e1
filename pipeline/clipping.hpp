#pragma once
// Homogeneous polygon clipping (GL 1.1 section 2.11): against the near and
// far planes, the user clip planes, and a guard band in x and y far outside
// the window (as llvmpipe does), so that coverage inside the viewport is
// decided by the rasterizer on the original edges, not on clipped ones.
#include <array>
#include <vector>

#include "pipeline/vecmath.hpp"

namespace mpr {

inline constexpr int kVaryings = 9;  // front RGBA, back RGBA, fog

struct ClipVertex {
  Vec4 clip;                         // clip coordinates
  std::array<float, kVaryings> attr;  // interpolated linearly in clip space
};

// A plane a x + b y + c z + d w >= 0 in clip coordinates.
using ClipPlane = Vec4;

// Guard band half-width in NDC units: window coordinates stay within a few
// times the largest window side, so fixed-point products fit in 64 bits.
inline constexpr float kGuardBand = 8.0f;

// Clips the convex polygon `poly` against every plane; the result may be empty.
// Intersections are always computed from the inside vertex towards the outside
// one, so the two triangles of a shared edge get the very same new vertex.
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> poly, const std::vector<ClipPlane>& planes);

// The fixed planes: near, far, and the x/y guard band.
const std::vector<ClipPlane>& viewVolumePlanes();

}  // namespace mpr
