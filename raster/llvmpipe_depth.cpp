// llvmpipe's depth planes for one MPR triangle (see llvmpipe_depth.hpp).
#include "raster/llvmpipe_depth.hpp"

#include <algorithm>
#include <bit>
#include <limits>

#include "raster/fixed_point.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

// draw_pt.c draw_vbo runs the draw module (its clipper, and llvmpipe's
// set-up behind it) with denormals flushed to zero
// (util_fpstate_set_denorms_to_zero, SSE's FTZ and DAZ): an operand below
// the smallest normal float counts as zero, and so does such a result. The
// clipper's arithmetic below follows it: where a plane distance of 1 meets
// one of 1e38, t = 1 / 1e38 is denormal, so draw's new vertex is the outer
// vertex itself, not one a unit away, and a rectangle of +-1e38 clips to
// nothing (glRectf -1.7e38 -1.7e38 1.7e38 1.7e38 draws no pixel).
inline float flushDenormal(float v) {
  return std::fabs(v) < std::numeric_limits<float>::min() ? std::copysign(0.0f, v) : v;
}
inline float addFtz(float a, float b) { return flushDenormal(flushDenormal(a) + flushDenormal(b)); }
inline float subFtz(float a, float b) { return flushDenormal(flushDenormal(a) - flushDenormal(b)); }
inline float mulFtz(float a, float b) { return flushDenormal(flushDenormal(a) * flushDenormal(b)); }
inline float divFtz(float a, float b) { return flushDenormal(flushDenormal(a) / flushDenormal(b)); }

LlWindow toLlWindow(const DrawVertex& v, const WindowTransform& t) {
  if (v.original) return llvmpipeWindow(v.clip, t);
  // draw_pipe_clip.c interp(): the same in C, unfused (denormals flushed)
  const float oow = divFtz(1.0f, v.clip.w);
  const float flippedTransY = static_cast<float>(t.fbHeight) - t.transY;
  auto map = [oow](float c, float scale, float trans) { return addFtz(mulFtz(mulFtz(c, oow), scale), trans); };
  return {map(v.clip.x, t.scaleX, t.transX), map(v.clip.y, -t.scaleY, flippedTransY),
          map(v.clip.z, t.scaleZ, t.transZ)};
}

// draw's fixed clip planes in its bit order (draw_context.c draw->plane[0..5],
// the clip mask bits of draw_llvm.c generate_clipmask): x <= w, x >= -w,
// y <= w, y >= -w, z >= -w, z <= w; user planes follow as bits 6 and up.
constexpr float kDrawPlanes[6][4] = {{-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1},
                                     {0, 1, 0, 1},  {0, 0, 1, 1}, {0, 0, -1, 1}};

Vec4 drawPlane(std::size_t i, const std::vector<ClipPlane>& userPlanes) {
  return i < 6 ? Vec4(kDrawPlanes[i][0], kDrawPlanes[i][1], kDrawPlanes[i][2], kDrawPlanes[i][3]) : userPlanes[i - 6];
}

// Clips a triangle as draw_pipe_clip.c do_clip_tri does (Mesa 22.3): plane by
// plane of `mask` (the vertices' clip masks together) in bit order, each new
// vertex interpolated from the vertex nearer the plane, out + t * (in - out)
// per component; the polygon keeps its first vertex, the provoking one of the
// fan emit_poly makes. (MPR's own clipper, which decides coverage, orders
// planes and intersections differently; the polygon is the same up to
// rounding.)
// `in` and `out` are the caller's storage, kept between triangles (no
// allocation per clipped triangle); the polygon is left in `in` (empty when
// a vertex is not finite).
void clipLikeDraw(const std::array<DrawVertex, 3>& tri, std::uint32_t mask, const std::vector<ClipPlane>& userPlanes,
                  std::vector<DrawVertex>& in, std::vector<DrawVertex>& out) {
  in.assign(tri.begin(), tri.end());
  // (Every operation with denormals flushed, as draw_vbo runs it.)
  auto dot4 = [](const Vec4& a, const Vec4& b) {
    return addFtz(addFtz(addFtz(mulFtz(a.x, b.x), mulFtz(a.y, b.y)), mulFtz(a.z, b.z)), mulFtz(a.w, b.w));
  };
  // interp(): position and every varying (all perspective-interpolated, the
  // colours' mode when not flat) out + t (in - out).
  auto linterp = [](float t, float o, float i) { return addFtz(o, mulFtz(t, subFtz(i, o))); };
  auto lerp = [&linterp](float t, const DrawVertex& o, const DrawVertex& i) {
    DrawVertex d{Vec4(linterp(t, o.clip.x, i.clip.x), linterp(t, o.clip.y, i.clip.y), linterp(t, o.clip.z, i.clip.z),
                      linterp(t, o.clip.w, i.clip.w)),
                 false, {}};
    for (int k = 0; k < kVaryings; ++k) d.attr[k] = linterp(t, o.attr[k], i.attr[k]);
    return d;
  };
  while (mask != 0 && in.size() >= 3) {
    const int planeIndex = std::countr_zero(mask);
    mask &= ~(1u << planeIndex);
    const Vec4 plane = drawPlane(static_cast<std::size_t>(planeIndex), userPlanes);
    out.clear();
    DrawVertex prev = in[0];
    float dpPrev = dot4(prev.clip, plane);
    if (!std::isfinite(dpPrev)) return in.clear();
    in.push_back(in[0]);
    for (std::size_t i = 1; i < in.size(); ++i) {
      const DrawVertex& v = in[i];
      const float dp = dot4(v.clip, plane);
      if (!std::isfinite(dp)) return in.clear();
      bool differentSign;
      if (dpPrev >= 0.0f) {
        out.push_back(prev);
        differentSign = dp < 0.0f;
      } else {
        differentSign = !(dp < 0.0f);
      }
      if (differentSign) {
        const float denom = subFtz(dp, dpPrev);
        if (dp < 0.0f)  // going out
          out.push_back(-dp < dpPrev ? lerp(divFtz(dp, denom), v, prev) : lerp(divFtz(-dpPrev, denom), prev, v));
        else  // coming back in
          out.push_back(-dpPrev < dp ? lerp(divFtz(-dpPrev, denom), prev, v) : lerp(divFtz(dp, denom), v, prev));
      }
      prev = v;
      dpPrev = dp;
    }
    in.swap(out);
  }
}

// lp_setup_tri.c calc_fixed_position: (v - pixel_offset) * FIXED_ONE in
// single precision, converted by cvtps2dq (nearest even; out of range or NaN
// gives INT32_MIN).
std::int64_t snapLikeLlvmpipe(float v) {
  const float f = (v - 0.5f) * 256.0f;
  if (!(std::fabs(f) < 2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int64_t>(std::nearbyint(f));
}

}  // namespace

MPR_CPU_CLONES void LlvmpipeDepth::add(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
  // draw_pipe_clip.c clip_tri: inside every plane passes as it is; outside
  // one plane with all three vertices is dropped; else clipped and fanned.
  const std::uint32_t ma = drawClipMask(a.clip, *userPlanes), mb = drawClipMask(b.clip, *userPlanes),
                      mc = drawClipMask(c.clip, *userPlanes);
  clipped = (ma | mb | mc) != 0;
  if (!clipped)  // set up from the vertices themselves (no copies of them)
    return setUp({&a.clip, &b.clip, &c.clip}, {&a.attr, &b.attr, &c.attr},
                 {llvmpipeWindow(a.clip, window), llvmpipeWindow(b.clip, window), llvmpipeWindow(c.clip, window)});
  if ((ma & mb & mc) != 0) return;
  const std::array<DrawVertex, 3> tri = {DrawVertex{a.clip, true, a.attr}, {b.clip, true, b.attr}, {c.clip, true, c.attr}};
  clipLikeDraw(tri, ma | mb | mc, *userPlanes, clipScratchIn, clipScratchOut);
  const std::vector<DrawVertex>& poly = clipScratchIn;
  for (std::size_t i = 2; i < poly.size(); ++i) {
    const DrawVertex &d0 = poly[i - 1], &d1 = poly[i], &d2 = poly[0];
    setUp({&d0.clip, &d1.clip, &d2.clip}, {&d0.attr, &d1.attr, &d2.attr},
          {toLlWindow(d0, window), toLlWindow(d1, window), toLlWindow(d2, window)});
  }
}

MPR_CPU_CLONES void LlvmpipeDepth::setUp(std::array<const Vec4*, 3> clip, std::array<const Varyings*, 3> attr,
                          std::array<LlWindow, 3> p) {
  // lp_setup_tri.c calc_fixed_position: the winding on 1/256-pixel positions
  // as its SSE path computes it: each position by cvtps2dq (a NaN or one
  // past 2^31 is INT32_MIN: a vertex at the clip-space origin, which the
  // clipper makes where an edge passes through it, has 0 * inf = NaN),
  // the differences in 32 bits, wrapping, their products in 64.
  auto fixed = [](float f) { return static_cast<std::uint32_t>(static_cast<std::int32_t>(snapLikeLlvmpipe(f))); };
  auto diff = [](std::uint32_t a, std::uint32_t b) { return static_cast<std::int64_t>(static_cast<std::int32_t>(a - b)); };
  const std::int64_t area = wrappingSub(diff(fixed(p[0].x), fixed(p[1].x)) * diff(fixed(p[2].y), fixed(p[0].y)),
                                        diff(fixed(p[2].x), fixed(p[0].x)) * diff(fixed(p[0].y), fixed(p[1].y)));
  if (area == 0) return;  // llvmpipe draws nothing
  const float ex = p[0].x - p[2].x, ey = p[0].y - p[2].y, fx = p[1].x - p[2].x, fy = p[1].y - p[2].y;
  const float drawDet = ex * fy - ey * fx;
  // y-down positions: a positive area here is counter-clockwise in GL's y-up window.
  const bool ccwUp = area > 0;
  if (area < 0) {
    std::swap(p[0], p[1]);
    std::swap(clip[0], clip[1]);
    std::swap(attr[0], attr[1]);
  }
  // init_args: ooa = 1 / (dx01 dy20 - dy01 dx20), the deltas times it.
  const float dx01 = p[0].x - p[1].x, dy01 = p[0].y - p[1].y;
  const float dx20 = p[2].x - p[0].x, dy20 = p[2].y - p[0].y;
  const float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
  // Set up where it is kept (a copy of its 300 bytes was a fifth of this).
  Triangle& t = triangles.emplace_back();
  t.dx20ooa = dx20 * ooa;
  t.dy20ooa = dy20 * ooa;
  t.dx01ooa = dx01 * ooa;
  t.dy01ooa = dy01 * ooa;
  t.x0Center = p[0].x - 0.5f;
  t.y0Center = p[0].y - 0.5f;
  t.ccwUp = ccwUp;
  t.drawDet = drawDet;
  const PlaneCoefficients z = t.plane(p[0].z, p[1].z, p[2].z);
  t.a0 = z.a0;
  t.dzdx = z.dadx;
  t.dzdy = z.dady;
  t.v = p;
  for (int i = 0; i < 3; ++i) {
    // generate_viewport (and the clipper's interp) keep 1 / w in the position's w.
    t.oow[i] = 1.0f / clip[i]->w;
    t.attr[i] = *attr[i];
  }
  for (int i = 0; i < 3; ++i) {
    const LlWindow& a = t.v[i];
    t.fixedX[i] = snapLikeLlvmpipe(a.x);
    t.fixedY[i] = snapLikeLlvmpipe(a.y);
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    constexpr std::int64_t kLimit = std::int64_t{1} << 23;  // 2^31 once shifted by 8
    const std::int64_t dx = t.fixedX[i] - t.fixedX[j], dy = t.fixedY[i] - t.fixedY[j];
    t.wrapsSteps = t.wrapsSteps || dx < -kLimit || dx >= kLimit || dy < -kLimit || dy >= kLimit;
  }
  for (int i = 0; i < 3; ++i) {
    // do_triangle_ccw: plane i runs from vertex i to i + 1; dcdx = y[i] -
    // y[i+1], dcdy = x[i] - x[i+1], c = dcdx x[i] - dcdy y[i], plus one on
    // the edges that own their ties: left edges, and the horizontal ones
    // with dcdy < 0 (GL's bottom edge: OSMesa's rows are flipped, so
    // llvmpipe's top-left rule is MPR's own left-bottom rule in y-up space;
    // measured: a rectangle's row on its bottom edge is drawn, on its top
    // edge not, whichever way it is wound).
    const int j = (i + 1) % 3;
    const std::int64_t dcdx = t.fixedY[i] - t.fixedY[j], dcdy = t.fixedX[i] - t.fixedX[j];
    t.c[i] = wrappingSub(wrappingMul(dcdx, t.fixedX[i]), wrappingMul(dcdy, t.fixedY[i]));
    if (dcdx < 0 || (dcdx == 0 && dcdy < 0)) t.c[i] = wrappingAdd(t.c[i], 1);
  }
}

PlaneCoefficients LlvmpipeDepth::Triangle::plane(float v0, float v1, float v2) const {
  const float da01 = v0 - v1, da20 = v2 - v0;
  PlaneCoefficients p;
  p.dadx = da01 * dy20ooa - da20 * dy01ooa;
  p.dady = da20 * dx01ooa - da01 * dx20ooa;
  p.a0 = v0 - (p.dadx * x0Center + p.dady * y0Center);
  return p;
}

bool LlvmpipeDepth::Triangle::covers(int x, int yDown) const {
  // lp_rast_tri_tmp.h: the pixel at (x, y) (its centre, the offset of
  // calc_fixed_position taken off) is inside when c + dcdy y - dcdx x > 0 on
  // every plane (the rasteriser tests c - 1 >= 0).
  const std::int64_t px = static_cast<std::int64_t>(x) * 256, py = static_cast<std::int64_t>(yDown) * 256;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t dcdx = fixedY[i] - fixedY[j], dcdy = fixedX[i] - fixedX[j];
    if (!(wrappingSub(wrappingAdd(c[i], wrappingMul(dcdy, py)), wrappingMul(dcdx, px)) > 0)) return false;
  }
  return true;
}

const LlvmpipeDepth::Triangle& LlvmpipeDepth::containing(int x, int yDown) const {
  for (const Triangle& t : triangles)
    if (t.covers(x, yDown)) return t;
  const double px = x + 0.5, py = yDown + 0.5;
  const Triangle* best = &triangles[0];
  double bestDistance = -std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangles) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const LlWindow& a = t.v[i];
      const LlWindow& b = t.v[(i + 1) % 3];
      const double ex = static_cast<double>(b.x) - a.x, ey = static_cast<double>(b.y) - a.y;
      // Computed here, not at set-up: a pixel no fan triangle covers is
      // rare (most triangles never ask), so set-up does not pay for it.
      const double length = std::hypot(ex, ey);
      if (length > 0.0) nearest = std::min(nearest, (ex * (a.y - py) - ey * (a.x - px)) / length);
    }
    if (nearest > bestDistance) {
      bestDistance = nearest;
      best = &t;
    }
  }
  return *best;
}

}  // namespace mpr
