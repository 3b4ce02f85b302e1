#pragma once
// Tessellation of lit faces for GL's per-vertex lighting (render.tessellation).
// GL lights a triangle at its corners and interpolates the colours
// (Gouraud): a wall that is one quad, its corners far from the light, is
// too dark in the middle. Splitting its triangles gives the lighting more
// places to be evaluated; the surface stays the same.
#include <cstdint>

#include "scene/scene.hpp"

namespace mpr {

// The cap on the divisions of one triangle's edges, and on the triangles
// one object may grow to (the divisions are lowered to stay under it).
inline constexpr int kMaxTessellationDivisions = 64;
inline constexpr std::size_t kMaxTessellatedTriangles = 2'000'000;

// render.tessellation auto (the default): GL lights a triangle at its
// corners and interpolates (Gouraud); how far that strays from the light at
// each point grows with an edge's length over its distance to the light
// (the angle it subtends from the light). Auto splits an object until its
// longest edge is at most this share of the distance from its bounding box
// to the nearest light. Chosen from the accuracy tables
// (docs/explanation/accuracy.md): on the default scene, edges of at most 1
// (about a quarter of its walls' distance to the light) took the error from
// 7.81 % to 1.64 %, and 0.5 or 0.25 gained nothing more (1.63 %).
inline constexpr double kAutoEdgeOverLightDistance = 0.25;
// Auto never splits one triangle into more than 16 x 16: a light almost on
// a large face would ask for the most divisions everywhere, at a cost the
// default must not pay unasked (a number given asks for up to 64).
inline constexpr int kMaxAutoTessellationDivisions = 16;

// Splits every triangle of every diffuse object into k x k triangles, one k
// per object: the smallest with every edge of the object at most `maxEdge`
// long after the split (kAutoTessellation: at most
// kAutoEdgeOverLightDistance of the object's distance to the nearest
// light). A point on an edge is computed from the edge's two ends in a
// fixed (lexicographic) order, so triangles sharing an edge share its
// points bit for bit: no cracks, no T-junctions. Specular objects keep
// their faces (the recursion looks through them as polygons).
void tessellateLitObjects(Scene& scene, float maxEdge);

// The triangles `scene` holds after tessellateLitObjects(scene, maxEdge),
// without building them (the loader holds it to the scene's budget).
std::uint64_t tessellatedTriangleCount(const Scene& scene, float maxEdge);

}  // namespace mpr
