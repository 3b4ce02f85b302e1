#pragma once
// The two decisions every assembled triangle meets, each written once: the
// route it takes through clipping (Mesa's draw module, then MPR's clipper)
// and its facing (culled, or which colours it takes). The draw stage asks
// them on its full path and on its early cull (DrawStage::culledBeforeSetUp),
// which is the full path's answer taken before any set-up.
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include "pipeline/draw/clipping.hpp"
#include "pipeline/draw/draw_snapshot.hpp"
#include "raster/clip_vertex.hpp"
#include "raster/fixed_point.hpp"
#include "raster/llvmpipe_depth.hpp"
#include "raster/triangle_rasterizer.hpp"

namespace mpr {

// --- coverage positions ------------------------------------------------------------

// The coverage vertex of a triangle drawn without the window map: its
// window position as llvmpipe computes and snaps it (fused, on OSMesa's
// flipped rows); false where that position is not finite.
inline bool snapLikeLlvmpipeRaster(const ClipVertex& v, const WindowTransform& window, SnappedVertex& out) {
  const LlWindow l = llvmpipeWindow(v.clip, window);
  if (!std::isfinite(l.x) || !std::isfinite(l.y)) return false;
  out = {snapToSubpixel(l.x), (static_cast<std::int64_t>(window.fbHeight) - 1) * kSubpixelOne - snapToSubpixel(l.y)};
  return true;
}

// --- facing (GL 1.1 section 2.13.1 two-sided colours, 3.5.1 culling) ----------

inline constexpr int kCulled = -1;

// The colours a triangle wound `ccw` (GL window space) takes: 0 the front
// set, 4 the back set (two-sided lighting); kCulled when culling drops it.
inline int facingColorOffset(const DrawSnapshot& s, bool ccw) {
  const bool front = s.frontFaceCcw == ccw;
  if (s.cullEnabled && (s.cullFace == CullFace::FrontAndBack || (s.cullFace == CullFace::Front) == front))
    return kCulled;
  return (front || !s.twoSidedColors) ? 0 : 4;
}

// A triangle's facing on its snapped coverage positions (whose winding
// decides it, as llvmpipe's set-up does on its fixed-point positions).
struct Facing {
  std::int64_t area2;  // twice the signed area, in subpixels squared
  int colorOffset;     // facingColorOffset, or kCulled with no area (nothing is covered)
  bool drawn() const { return colorOffset != kCulled; }
};

inline Facing facingOf(const DrawSnapshot& s, const std::array<SnappedVertex, 3>& v) {
  const std::int64_t area = signedArea2(v[0], v[1], v[2]);
  if (area == 0) return {0, kCulled};
  return {area, facingColorOffset(s, area > 0)};
}

// Mesa's draw pipeline culls each triangle of a fan it clipped (its cull
// stage follows the clip stage) on the float determinant of its window
// positions (LlvmpipeDepth::Triangle::drawDet); a NaN det is not zero and
// not below zero: back-facing, as a zero one.
inline bool drawCullStageCulls(const DrawSnapshot& s, float drawDet) {
  if (!s.cullEnabled) return false;
  if (drawDet != 0.0f) return facingColorOffset(s, drawDet < 0.0f) == kCulled;
  return s.cullFace != CullFace::Front;
}

// --- route through clipping ------------------------------------------------------

enum class TriangleRoute : std::uint8_t {
  Dropped,      // a position or attribute not finite, or unclipped with w <= 0: touches nothing
  LlvmpipeFan,  // Mesa's draw module clips it: llvmpipe rasterises the fan it makes
  Unclipped,    // inside every plane: set up as it is
  Clipped,      // cut by MPR's clipper (the window map's planes), then fanned
};

inline bool finiteVertex(const ClipVertex& v) {
  if (!std::isfinite(v.clip.x) || !std::isfinite(v.clip.y) || !std::isfinite(v.clip.z) || !std::isfinite(v.clip.w))
    return false;
  for (float a : v.attr)
    if (!std::isfinite(a)) return false;
  return true;
}

// `drawModuleClips`: some vertex has a bit of Mesa's draw clip mask
// (drawClipMask, LlvmpipeDepth::clipped); false with a window map, which
// replaces llvmpipe's clipping by MPR's.
inline TriangleRoute routeTriangle(const DrawSnapshot& s, const std::array<ClipVertex, 3>& tri, bool drawModuleClips) {
  // A vertex that is not finite drops its primitive and touches nothing else.
  for (const ClipVertex& v : tri)
    if (!finiteVertex(v)) return TriangleRoute::Dropped;
  // Where Mesa's draw module clips the triangle, llvmpipe rasterises the fan
  // draw makes of it, so that fan decides the coverage (and its planes the
  // depth); MPR's own clipper would cover slightly other pixels along the
  // edges clipping makes (issue 17 class 4, large_coordinates_clip.gls).
  if (drawModuleClips) return TriangleRoute::LlvmpipeFan;
  // Inside every plane, clipPolygon would return the triangle as it is.
  // Without a window map, draw's clip masks all clear means the six
  // view-volume planes hold already: for finite vertices each of their
  // distances is the very sum drawClipMask compares (x + w, w - x, ...), and
  // only the user planes, which drawClipMask evaluates fused, are asked again.
  const std::span<const ClipPlane> planes =
      std::span<const ClipPlane>(s.clipPlanes).subspan(s.windowMap ? 0 : DrawSnapshot::kViewVolumePlanes);
  if (!insideAllPlanes(tri, planes)) return TriangleRoute::Clipped;
  for (const ClipVertex& v : tri)
    if (!(v.clip.w > 0.0f)) return TriangleRoute::Dropped;
  return TriangleRoute::Unclipped;
}

}  // namespace mpr
