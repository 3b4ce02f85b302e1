#pragma once
// Triangle coverage with exact integer edge functions and a top-left fill
// rule, so that triangles sharing an edge never both cover a pixel and a fan
// around a point covers each pixel exactly once. The rasterizer knows nothing
// of GL state: it reports covered pixels and their screen-space barycentric
// weights; the caller interpolates what it needs.
//
// Work is bounded by a clip rectangle, so a caller may split the window into
// tiles and run them on separate threads: coverage of a pixel depends only on
// the triangle, never on the tile it falls in.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

#include "raster/fixed_point.hpp"

namespace mpr {

struct PixelBounds {  // half-open [x0, x1) x [y0, y1)
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Window position of one vertex, already snapped.
struct SnappedVertex {
  std::int64_t x = 0, y = 0;
};

inline SnappedVertex snapVertex(float x, float y) { return {snapToSubpixel(x), snapToSubpixel(y)}; }

// Twice the signed area in fixed point: positive when counter-clockwise in
// GL window coordinates (y up).
inline std::int64_t signedArea2(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Which ties (pixel centre exactly on an edge) belong to the triangle: the
// top-left rule of a y-down framebuffer (D3D, Gallium), as Mesa's llvmpipe
// applies it to OSMesa's buffers. In GL window coordinates (y up) that is:
// centres on a left edge and on a horizontal bottom edge belong to the
// triangle; those on a right or a horizontal top edge do not. (Measured
// against llvmpipe; softpipe differs on such centres.)
inline bool ownsTies(std::int64_t dx, std::int64_t dy) {
  // Counter-clockwise in y-up coordinates: the interior lies left of each
  // edge, left edges run downwards and the bottom edge runs left to right.
  return dy < 0 || (dy == 0 && dx > 0);
}

// One row's covered pixels: x, x + 1, ..., x + count - 1 on row y. The
// edge-function weight of vertex i at pixel x + k is w[i] + k * stepX[i]
// (vertex order as the caller gave it).
struct CoveredSpan {
  int x, y, count;
  std::array<std::int64_t, 3> w, stepX;
};

// Calls emitSpan(const CoveredSpan&) for every row's covered pixels inside
// `clip`, rows bottom to top, where the weights are the (integer) edge
// functions of vertex i; their sum is the doubled area. Degenerate triangles
// cover nothing. With rowStride n > 1 only the rows y with y mod n ==
// rowPhase are visited (a thread's share of a draw's rows, interleaved so
// that every thread gets as many pixels).
template <typename EmitSpan>
void rasterizeTriangleSpans(const std::array<SnappedVertex, 3>& vIn, const PixelBounds& clip, EmitSpan&& emitSpan,
                            int rowStride = 1, int rowPhase = 0) {
  std::array<SnappedVertex, 3> v = vIn;
  std::int64_t area = signedArea2(v[0], v[1], v[2]);
  if (area == 0) return;
  // Normalise to counter-clockwise; remember the swap to report weights in the
  // caller's vertex order.
  const bool swapped = area < 0;
  if (swapped) {
    std::swap(v[1], v[2]);
    area = -area;
  }

  std::int64_t minX = std::min({v[0].x, v[1].x, v[2].x}), maxX = std::max({v[0].x, v[1].x, v[2].x});
  std::int64_t minY = std::min({v[0].y, v[1].y, v[2].y}), maxY = std::max({v[0].y, v[1].y, v[2].y});
  const std::int64_t px0 = std::max<std::int64_t>(clip.x0, ceilDivSubpixel(minX));
  const std::int64_t px1 = std::min<std::int64_t>(clip.x1 - 1, floorDivSubpixel(maxX));
  const std::int64_t py0 = std::max<std::int64_t>(clip.y0, ceilDivSubpixel(minY));
  const std::int64_t py1 = std::min<std::int64_t>(clip.y1 - 1, floorDivSubpixel(maxY));
  if (px0 > px1 || py0 > py1) return;

  // Edge i is opposite vertex i: E_i(p) = cross(v[j] - v[k], p - v[k])... written
  // so that E_i at vertex i equals the doubled area, making E_i the weight of i.
  struct Edge {
    std::int64_t stepX, stepY, rowStart;
    std::int64_t bias;  // 0 for edges that own ties, 1 otherwise (test is E - bias >= 0)
  };
  std::array<Edge, 3> e{};
  for (int i = 0; i < 3; ++i) {
    const SnappedVertex& a = v[(i + 1) % 3];
    const SnappedVertex& b = v[(i + 2) % 3];
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    // E(p) = dx * (p.y - a.y) - dy * (p.x - a.x): positive left of a->b.
    e[i].stepX = -dy * kSubpixelOne;
    e[i].stepY = dx * kSubpixelOne;
    e[i].rowStart = dx * (py0 * kSubpixelOne - a.y) - dy * (px0 * kSubpixelOne - a.x);
    e[i].bias = ownsTies(dx, dy) ? 0 : 1;
  }

  // Each row's covered pixels are one span (the triangle is convex): its
  // ends are solved from the edge functions in exact integer arithmetic, so
  // the span holds exactly the pixels a test of every pixel would pass, and
  // the weights handed on are the same integers.
  const std::int64_t width = px1 - px0;
  // The first row of this phase, and the edge functions advanced to it.
  std::int64_t first = py0;
  if (rowStride > 1) {
    const std::int64_t r = ((py0 % rowStride) + rowStride) % rowStride;
    first = py0 + ((rowPhase - r) % rowStride + rowStride) % rowStride;
    for (int i = 0; i < 3; ++i) e[i].rowStart += (first - py0) * e[i].stepY;
  }
  for (std::int64_t py = first; py <= py1; py += rowStride) {
    std::int64_t k0 = 0, k1 = width;  // the span, as offsets from px0
    for (int i = 0; i < 3 && k0 <= k1; ++i) {
      const std::int64_t slack = e[i].rowStart - e[i].bias;  // E - bias at px0; covered where >= 0
      if (e[i].stepX > 0) k0 = std::max(k0, slack >= 0 ? 0 : (-slack + e[i].stepX - 1) / e[i].stepX);
      else if (e[i].stepX < 0) k1 = slack < 0 ? -1 : std::min(k1, slack / -e[i].stepX);
      else if (slack < 0) k1 = -1;
    }
    if (k0 <= k1) {
      CoveredSpan span{static_cast<int>(px0 + k0), static_cast<int>(py), static_cast<int>(k1 - k0 + 1), {}, {}};
      for (int i = 0; i < 3; ++i) {
        const int to = swapped && i > 0 ? 3 - i : i;  // weights back in the caller's vertex order
        span.w[to] = e[i].rowStart + k0 * e[i].stepX;
        span.stepX[to] = e[i].stepX;
      }
      emitSpan(span);
    }
    e[0].rowStart += rowStride * e[0].stepY;
    e[1].rowStart += rowStride * e[1].stepY;
    e[2].rowStart += rowStride * e[2].stepY;
  }
}

// Calls emit(x, y, w0, w1, w2) for every covered pixel inside `clip`, pixel
// by pixel (the spans of rasterizeTriangleSpans, walked).
template <typename Emit>
void rasterizeTriangle(const std::array<SnappedVertex, 3>& v, const PixelBounds& clip, Emit&& emit, int rowStride = 1,
                       int rowPhase = 0) {
  rasterizeTriangleSpans(
      v, clip,
      [&](const CoveredSpan& s) {
        for (int k = 0; k < s.count; ++k)
          emit(s.x + k, s.y, s.w[0] + k * s.stepX[0], s.w[1] + k * s.stepX[1], s.w[2] + k * s.stepX[2]);
      },
      rowStride, rowPhase);
}

}  // namespace mpr
