#pragma once
// Homogeneous polygon clipping (GL 1.1 section 2.11): against the six planes
// of the view volume and the user clip planes. Like Mesa's draw module in
// front of llvmpipe, x and y are clipped at the viewport itself (no guard
// band): a vertex outside the viewport is replaced by one on its border, which
// is then snapped, and that decides ties on the edges it creates (measured:
// a guard band changes coverage of centres lying exactly on such edges).
#include <array>
#include <span>
#include <vector>

#include "raster/clip_vertex.hpp"
#include "util/vecmath.hpp"

namespace mpr {

// Half-width of the x/y clip volume in NDC units: 1, the viewport itself.
inline constexpr float kGuardBand = 1.0f;

// Clips the convex polygon `poly` against every plane; the result may be empty.
// Intersections are always computed from the inside vertex towards the outside
// one, so the two triangles of a shared edge get the very same new vertex.
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> poly, const std::vector<ClipPlane>& planes);

// The fixed planes: near, far, left, right, bottom, top.
const std::vector<ClipPlane>& viewVolumePlanes();

// Whether every vertex lies inside every plane (distance >= 0, as
// clipPolygon measures it): then clipPolygon returns the triangle unchanged.
bool insideAllPlanes(const std::array<ClipVertex, 3>& tri, std::span<const ClipPlane> planes);

}  // namespace mpr
