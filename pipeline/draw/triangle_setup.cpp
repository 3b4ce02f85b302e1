// DrawStage: llvmpipe's triangle set-up (lp_setup_tri.c) as the draw stage
// dispatches it: a triangle drawn as it is, or cut by MPR's clipper
// (rasterizeClippedTriangle: coverage on llvmpipe's snapped positions,
// llvmpipe's depth and colour planes), and the fan Mesa's draw module makes
// of a triangle it clips (rasterizeLlvmpipeFan, with llvmpipe's tiles where
// a triangle's fixed-point steps wrap). Each set-up is drawn now or kept for
// the row threads (row_drawing.cpp).
#include <algorithm>
#include <cmath>
#include <optional>

#include "pipeline/draw/draw_stage.hpp"
#include "pipeline/draw/triangle_decisions.hpp"
#include "raster/fixed_point.hpp"
#include "raster/llvmpipe_math.hpp"
#include "util/check.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

// Whether the fragments' colour is read: a colour channel is written, or
// the alpha test looks at alpha.
bool needsColor(const FragmentState& s) {
  return s.colorMask[0] || s.colorMask[1] || s.colorMask[2] || s.colorMask[3] || s.alpha.enabled;
}

}  // namespace

MPR_CPU_CLONES void DrawStage::rasterizeClippedTriangle(const DrawSnapshot& s, const ClipVertex& a, const ClipVertex& b,
                                                        const ClipVertex& c, const LlvmpipeDepth& depth) {
  const ClipVertex* v[3] = {&a, &b, &c};
  std::array<SnappedVertex, 3> snapped;
  double invW[3], xWin[3], yWin[3], mapZ[3] = {0.0, 0.0, 0.0}, mapInvQ[3] = {1.0, 1.0, 1.0};
  for (int i = 0; i < 3; ++i) {
    const float iw = 1.0f / v[i]->clip.w;
    float xn = v[i]->clip.x * iw, yn = v[i]->clip.y * iw;
    if (s.windowMap) {
      // [u v q] = [x y 1] M on normalised device coordinates; the vertex
      // goes to (u/q, v/q) and keeps its depth. Attributes and depth are then
      // interpolated as in the unmapped image: a projective map divides the
      // screen-space weights by q (so 1/w becomes 1/(w q), and depth, linear
      // on the unmapped screen, is weighted by 1/q).
      const glm::mat3& m = *s.windowMap;
      const float q = m[2][0] * xn + m[2][1] * yn + m[2][2];
      if (!(q > 0.0f)) return;  // clipped to q >= |u|: only a point can reach q = 0
      const float u = m[0][0] * xn + m[0][1] * yn + m[0][2], w = m[1][0] * xn + m[1][1] * yn + m[1][2];
      mapZ[i] = static_cast<double>(v[i]->clip.z * iw * depth.window.scaleZ + depth.window.transZ);
      mapInvQ[i] = 1.0 / static_cast<double>(q);
      xn = u / q;
      yn = w / q;
    }
    const float xw = xn * s.window.scaleX + s.window.transX;
    const float yw = yn * s.window.scaleY + s.window.transY;
    // A denormal w (1/w = inf) puts the vertex at an infinite window
    // position: the primitive is dropped like one with a non-finite vertex.
    if (!std::isfinite(xw) || !std::isfinite(yw)) return;
    invW[i] = static_cast<double>(iw) * mapInvQ[i];
    xWin[i] = xw;
    yWin[i] = yw;
    if (s.windowMap) {
      snapped[i] = snapVertex(xw, yw);
    } else {
      // Coverage from the window position llvmpipe snaps (fused, on OSMesa's
      // flipped rows): MPR's unfused y-up position can differ by an ulp, and
      // on a sliver that moves a pixel centre across an edge (lighting seed
      // 1113).
      if (!snapLikeLlvmpipeRaster(*v[i], depth.window, snapped[i])) return;
    }
  }
  const Facing facing = facingOf(s, snapped);
  if (!facing.drawn()) return;
  const std::int64_t area = facing.area2;
  const int colorOffset = facing.colorOffset;

  const PixelRect& region = s.drawRegion;
  if (region.empty()) return;
  const PixelBounds bounds{region.x0, region.y0, region.x1, region.y1};
  // Where llvmpipe's clipping dropped what MPR's kept, MPR's own triangle
  // stands in (it is then at most a few pixels of an edge).
  std::optional<LlvmpipeDepth> fallback;  // (its vectors made only when it is)
  if (depth.triangles.empty()) {
    fallback.emplace(LlvmpipeDepth{depth.window, depth.userPlanes, {}});
    if (!s.windowMap) fallback->add(a, b, c);
  }
  const LlvmpipeDepth& depthPlanes = fallback ? *fallback : depth;

  // The triangle's rows within the region: none, and nothing is set up.
  const std::int64_t top = std::max({snapped[0].y, snapped[1].y, snapped[2].y});
  const std::int64_t bottom = std::min({snapped[0].y, snapped[1].y, snapped[2].y});
  const std::int64_t rowLo = std::max<std::int64_t>(bounds.y0, ceilDivSubpixel(bottom));
  const std::int64_t rowHi = std::min<std::int64_t>(bounds.y1 - 1, floorDivSubpixel(top));
  if (rowLo > rowHi) return;
  // Several planes are looked up in a set-up that lives for this call only:
  // such a triangle is drawn now, after what the draw has deferred. Any
  // other is set up where the draw keeps it (no copy of the set-up).
  const bool severalPlanes = s.frag.depth.enabled && !s.windowMap && depthPlanes.triangles.size() > 1;
  const bool deferred = deferring_ && !severalPlanes;
  ClippedTriangleRows drawnNow;
  ClippedTriangleRows& job = deferred ? deferClipped() : drawnNow;
  job.snapped = snapped;
  job.bounds = bounds;

  // Coverage is decided on the snapped vertices; colours are interpolated on
  // the unsnapped window positions, as llvmpipe sets up its planes (depth
  // follows llvmpipe's own arithmetic, see LlvmpipeDepth). All of it is set
  // up here once; shadeSpan does the per-pixel part a row span at a time.
  TriangleShading& t = job.shading;
  t.depthMax = static_cast<float>(fb_.profile().depthMax());
  t.fbHeight = fb_.height();
  if (s.frag.depth.enabled) {
    if (s.windowMap) {
      t.depth = TriangleShading::Depth::WindowMap;
      for (int i = 0; i < 3; ++i) {
        t.mapZ[i] = mapZ[i];
        t.mapInvQ[i] = mapInvQ[i];
      }
    } else if (depthPlanes.triangles.size() == 1) {
      t.depth = TriangleShading::Depth::OnePlane;
      t.a0 = depthPlanes.triangles[0].a0;
      t.dzdx = depthPlanes.triangles[0].dzdx;
      t.dzdy = depthPlanes.triangles[0].dzdy;
    } else if (!depthPlanes.triangles.empty()) {
      t.depth = TriangleShading::Depth::Planes;
      t.planes = &depthPlanes;
    }
  }
  t.color = needsColor(s.frag);
  t.uniformColor = s.uniformColor;
  if (s.fog.enabled) t.fog = &s.fog;
  // llvmpipe draws the triangle as one: its colours are that triangle's
  // planes (also where MPR's own clipper made pieces of it).
  t.llvmpipeColor = t.color && !s.windowMap && depthPlanes.triangles.size() == 1;
  if (t.llvmpipeColor)
    setUpChannelPlanes(depthPlanes.triangles[0], colorOffset, t.uniformColor, t.fog != nullptr, t.channels);
  // The exact weights and the vertices' channels: read by shadeSpan only
  // for MPR's own colours or the window map's depth (most triangles, those
  // of llvmpipe's colour planes or of no colour, skip them).
  if ((t.color && !t.llvmpipeColor) || t.depth == TriangleShading::Depth::WindowMap) {
    t.ex1 = xWin[1] - xWin[0];
    t.ey1 = yWin[1] - yWin[0];
    t.ex2 = xWin[2] - xWin[0];
    t.ey2 = yWin[2] - yWin[0];
    t.xWin0 = xWin[0];
    t.yWin0 = yWin[0];
    t.exactArea = t.ex1 * t.ey2 - t.ex2 * t.ey1;
    t.useSnapped = !(std::fabs(t.exactArea) > 0.0);  // degenerate before snapping
    t.snappedArea = static_cast<double>(area > 0 ? area : -area);  // the weights' sum
    for (int i = 0; i < 3; ++i) t.invW[i] = invW[i];
    vertexChannels(a, b, c, colorOffset, t.attr, t.constant);
    decideFlatColor(t);
  }

  if (!deferred) drawNow(s, job);
}

void DrawStage::rasterizeLlvmpipeFan(const DrawSnapshot& s, const LlvmpipeDepth& depth) {
  if (depth.triangles.empty()) return;  // llvmpipe draws nothing of it
  ++counters_.trianglesDrawn;
  const PixelRect& region = s.drawRegion;
  if (region.empty()) return;
  const int fbHeight = fb_.height();
  FanShading shading;
  shading.depthMax = static_cast<float>(fb_.profile().depthMax());
  shading.fbHeight = fbHeight;
  shading.depth = s.frag.depth.enabled;
  shading.color = needsColor(s.frag);
  if (s.fog.enabled) shading.fog = &s.fog;
  // The region in llvmpipe's y-down rows.
  const int rowLo = fbHeight - region.y1, rowHi = fbHeight - 1 - region.y0;
  for (const LlvmpipeDepth::Triangle& t : depth.triangles) {
    if (drawCullStageCulls(s, t.drawDet)) continue;
    const int colorOffset = facingColorOffset(s, t.ccwUp);
    if (colorOffset < 0) continue;
    FanTriangleRows job{shading, t, 0, 0, 0, 0};
    FanShading& fan = job.shading;
    fan.a0 = t.a0;
    fan.dzdx = t.dzdx;
    fan.dzdy = t.dzdy;
    if (fan.color) setUpChannelPlanes(t, colorOffset, s.uniformColor, fan.fog != nullptr, fan.planes);
    // Bounds of the pixels whose centres the fixed-point edges can cover
    // (positions are (v - 0.5) * 256: pixel x's centre is at x * 256).
    const std::int64_t minX = std::min({t.fixedX[0], t.fixedX[1], t.fixedX[2]}),
                       maxX = std::max({t.fixedX[0], t.fixedX[1], t.fixedX[2]});
    const std::int64_t minY = std::min({t.fixedY[0], t.fixedY[1], t.fixedY[2]}),
                       maxY = std::max({t.fixedY[0], t.fixedY[1], t.fixedY[2]});
    job.x0 = std::max<std::int64_t>(region.x0, floorDivide(minX, 256));
    job.x1 = std::min<std::int64_t>(region.x1 - 1, floorDivide(maxX, 256) + 1);
    job.y0 = std::max<std::int64_t>(rowLo, floorDivide(minY, 256));
    job.y1 = std::min<std::int64_t>(rowHi, floorDivide(maxY, 256) + 1);
    if (t.wrapsSteps) {
      // lp_setup.c draw_regions: the framebuffer, within the scissor box
      // (not the viewport). Blocks are filled whole past the triangle's own
      // box, and so past the region where the box kept llvmpipe from adding
      // a scissor plane on that side: any pixel of the framebuffer.
      const PixelRect& r = s.scissoredFramebuffer;
      if (r.empty()) continue;
      job.llvmpipeRegion = {r.x0, fbHeight - r.y1, r.x1 - 1, fbHeight - 1 - r.y0};
      job.x0 = 0;
      job.x1 = fb_.width() - 1;
      job.y0 = 0;
      job.y1 = fbHeight - 1;
    }
    if (job.x0 > job.x1 || job.y0 > job.y1) continue;
    if (deferring_) {
      defer(job);
      continue;
    }
    drawNow(s, job);
  }
}


}  // namespace mpr
