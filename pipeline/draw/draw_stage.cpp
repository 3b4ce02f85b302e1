// DrawStage: a draw's primitives assembled, routed through clipping and
// culled (triangle_decisions.hpp), each triangle handed to llvmpipe's
// set-up (triangle_setup.cpp).
#include "pipeline/draw/draw_stage.hpp"

#include <algorithm>
#include <utility>

#include "pipeline/draw/clipping.hpp"
#include "pipeline/draw/triangle_decisions.hpp"
#include "raster/fixed_point.hpp"
#include "util/check.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

// Whether signedArea2 of snapped positions this close to the origin is
// exact: coordinates below 2^30 keep each product below 2^62.
inline bool areaCannotOverflow(const SnappedVertex& v) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 30;
  return v.x > -kLimit && v.x < kLimit && v.y > -kLimit && v.y < kLimit;
}

}  // namespace

bool DrawStage::runsDrawPipeline(const DrawSnapshot& s, std::span<const ClipVertex> vertices, std::size_t count) {
  MPR_DCHECK(count <= vertices.size());
  for (std::size_t i = 0; i < count; ++i)
    if (drawClipMask(vertices[i].clip, s.userPlanes) != 0) return true;
  return false;
}

void DrawStage::draw(const DrawSnapshot& s, PrimitiveType type, std::span<const ClipVertex> processed,
                     bool quadsOtherDiagonal) {
  MPR_DCHECK(pipelineMatches(s));
  MPR_DCHECK(s.clipPlanes.size() == DrawSnapshot::kViewVolumePlanes + s.userPlanes.size());
  MPR_DCHECK_EQ(s.window.fbHeight, fb_.height());
  std::vector<AssembledTriangle> tris = assembleTriangles(type, static_cast<std::uint32_t>(processed.size()));
  if (tris.empty()) return;
  if (type == PrimitiveType::QuadStrip && !runsDrawPipeline(s, processed, processed.size() & ~std::size_t{1})) {
    // A quad strip is (2, 0, 3) then (0, 1, 3) per quad through the draw
    // module's pipeline (draw_decompose_tmp.h, QUAD(2, 0, 1, 3)), which runs
    // when any vertex lies outside a clip plane; otherwise llvmpipe's setup
    // (lp_setup_vbuf.c) draws the same two triangles in the other order,
    // (0, 1, 3) first, which decides the pixels where a quad overlaps itself.
    // The vbo trims the strip to an even count first: a last odd vertex takes
    // no part in the decision.
    for (std::size_t k = 0; k + 1 < tris.size(); k += 2) std::swap(tris[k], tris[k + 1]);
  }
  if (type == PrimitiveType::Quads && quadsOtherDiagonal)
    for (std::size_t k = 0; k < tris.size(); k += 2) {
      const std::uint32_t q = tris[k].v[0];  // MPR's quad triangles both start at the quad's first vertex
      tris[k] = {{q, q + 1, q + 3}, q + 3};
      tris[k + 1] = {{q + 1, q + 2, q + 3}, q + 3};
    }

  // The state cannot change within a draw: one set of llvmpipe planes is
  // reused (no allocation per triangle once it has grown). With threads and
  // no observer the triangles are set up here and queued together at the
  // end, for the row threads to draw (drawDeferred).
  beginDraw(s);
  LlvmpipeDepth depth{s.window, &s.userPlanes, {}};
  const bool cullsBeforeSetUp = s.cullEnabled && !s.windowMap;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    beforeTriangle(s, tris.size() - k);
    const AssembledTriangle& t = tris[k];
    std::array<ClipVertex, 3> tri = {processed[t.v[0]], processed[t.v[1]], processed[t.v[2]]};
    if (s.flatShading)
      for (ClipVertex& cv : tri)
        for (int i = 0; i < 8; ++i) cv.attr[i] = processed[t.provoking].attr[i];
    // A culled triangle llvmpipe does not clip is dropped before its
    // set-up, counted as drawTriangle counts it (with culling on, half of a
    // closed mesh's triangles face away: 214 000 of the bathroom trace's
    // 480 000 unclipped ones were set up only to be culled).
    if (cullsBeforeSetUp && culledBeforeSetUp(s, tri)) {
      ++counters_.triangles;
      ++counters_.trianglesDrawn;
      continue;
    }
    depth.triangles.clear();
    // The end-of-pipeline stage interpolates depth itself (only the window
    // transform is used): no llvmpipe planes to set up.
    if (!s.windowMap) depth.add(tri[0], tri[1], tri[2]);
    drawTriangle(s, tri, depth);
  }
  endDraw(s);
}

MPR_CPU_CLONES bool DrawStage::culledBeforeSetUp(const DrawSnapshot& s, const std::array<ClipVertex, 3>& tri) const {
  // rasterizeClippedTriangle's facing first, before anything it sets up (a
  // triangle it draws costs no more than this): a vertex whose position is
  // not finite, no area, or culled.
  std::array<SnappedVertex, 3> snapped;
  bool finite = true;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!snapLikeLlvmpipeRaster(tri[i], s.window, snapped[i])) {
      finite = false;
    } else if (!areaCannotOverflow(snapped[i])) {
      // A vertex near the eye plane (w a hair above 0) snaps far enough out
      // that the area's products would overflow: the full path decides
      // (such a triangle is clipped, so this one would not drop it anyway).
      return false;
    }
  }
  if (finite && facingOf(s, snapped).drawn()) return false;
  // Then whether drawTriangle takes it there: unclipped by draw and by MPR.
  const bool drawModuleClips = (drawClipMask(tri[0].clip, s.userPlanes) | drawClipMask(tri[1].clip, s.userPlanes) |
                                drawClipMask(tri[2].clip, s.userPlanes)) != 0;
  return routeTriangle(s, tri, drawModuleClips) == TriangleRoute::Unclipped;
}

void DrawStage::drawTriangle(const DrawSnapshot& s, const std::array<ClipVertex, 3>& tri, const LlvmpipeDepth& depth) {
  ++counters_.triangles;
  switch (routeTriangle(s, tri, !s.windowMap && depth.clipped)) {
    case TriangleRoute::Dropped: return;
    case TriangleRoute::LlvmpipeFan: return rasterizeLlvmpipeFan(s, depth);
    case TriangleRoute::Unclipped:
      ++counters_.trianglesDrawn;
      return rasterizeClippedTriangle(s, tri[0], tri[1], tri[2], depth);
    case TriangleRoute::Clipped: break;
  }
  std::vector<ClipVertex> poly(tri.begin(), tri.end());
  poly = clipPolygon(std::move(poly), s.clipPlanes);
  if (poly.size() < 3) return;
  for (const ClipVertex& v : poly)
    if (!(v.clip.w > 0.0f)) return;  // only the point (0,0,0,0) survives clipping with w <= 0
  ++counters_.trianglesDrawn;
  for (size_t i = 1; i + 1 < poly.size(); ++i) rasterizeClippedTriangle(s, poly[0], poly[i], poly[i + 1], depth);
}

}  // namespace mpr
