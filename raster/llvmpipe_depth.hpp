#pragma once
// llvmpipe's depth arithmetic, reproduced bit for bit for MPR's triangles:
// the window transform Mesa's state tracker hands llvmpipe, the draw
// module's clipper and fan, and llvmpipe's single-precision depth planes.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/clip_vertex.hpp"
#include "util/vecmath.hpp"

namespace mpr {

// The viewport transform as Mesa's state tracker hands it to llvmpipe: OSMesa
// draws into a window-system buffer, so y is flipped (st_atom_viewport.c:
// scale[1] = -scale[1], translate[1] = fb_height - translate[1]) and llvmpipe
// counts rows downwards from the top.
struct WindowTransform {
  float scaleX, transX, scaleY, transY, scaleZ, transZ;
  int fbHeight;
};

// A clip-space vertex as Mesa's draw module carries it: `original` for one
// that came out of the vertex shader, false for one the clipper made; its
// varyings (front and back colour, fog coordinate) beside it.
struct DrawVertex {
  Vec4 clip;
  bool original;
  std::array<float, kVaryings> attr;
};

// One attribute's plane as llvmpipe sets it up (lp_state_setup.c
// calc_coef4, single precision, unfused): relative to the window origin,
// a0 being the value at pixel (0, 0)'s centre.
struct PlaneCoefficients {
  float a0 = 0.0f, dadx = 0.0f, dady = 0.0f;
  // lp_bld_interp.c attribs_update_simple: a0 + x dadx + y dady as two fused
  // lp_build_fmuladd (this CPU has FMA), x and y the integer pixel corner in
  // llvmpipe's y-down space.
  float at(float x, float yDown) const { return std::fma(dady, yDown, std::fma(dadx, x, a0)); }
};

struct LlWindow {  // window position in llvmpipe's y-down space
  float x, y, z;
};

// Where llvmpipe puts a vertex that came out of the vertex shader (draw_llvm.c
// generate_viewport): (clip * 1/w) * scale + translate, one fused
// multiply-add, on OSMesa's flipped rows. Inline: in the set-up's x86-64-v3
// clones (MPR_CPU_CLONES) each std::fma is one instruction.
inline LlWindow llvmpipeWindow(const Vec4& clip, const WindowTransform& t) {
  const float oow = 1.0f / clip.w;
  const float flippedTransY = static_cast<float>(t.fbHeight) - t.transY;
  return {std::fma(clip.x * oow, t.scaleX, t.transX), std::fma(clip.y * oow, -t.scaleY, flippedTransY),
          std::fma(clip.z * oow, t.scaleZ, t.transZ)};
}

// The vertex's clip mask as draw_llvm.c generate_clipmask computes it: bit
// i set where the vertex lies outside draw's plane i (the order of
// kDrawPlanes in llvmpipe_depth.cpp), user planes as bits 6 and up. Inline,
// for the set-up's clones.
inline std::uint32_t drawClipMask(const Vec4& p, const std::vector<ClipPlane>& userPlanes) {
  std::uint32_t m = 0;
  if (p.x > p.w) m |= 1u;
  if (p.x + p.w < 0.0f) m |= 2u;
  if (p.y > p.w) m |= 4u;
  if (p.y + p.w < 0.0f) m |= 8u;
  if (p.z + p.w < 0.0f) m |= 16u;
  if (p.z > p.w) m |= 32u;
  for (std::size_t i = 0; i < userPlanes.size(); ++i) {
    const Vec4& u = userPlanes[i];
    const float d = std::fma(u.w, p.w, std::fma(u.z, p.z, std::fma(u.y, p.y, u.x * p.x)));
    if (0.0f > d || !std::isfinite(d)) m |= 1u << (6 + i);
  }
  return m;
}

// llvmpipe's depth for the fragments of one MPR triangle, bit for bit.
//
// llvmpipe does not interpolate the exact plane: it sets up a0, dz/dx, dz/dy
// in single precision at the window origin and evaluates them per pixel, so
// its depths drift from the exact plane by up to about +-1.5 units of 2^24;
// this reproduces that arithmetic, and the triangles it is applied to:
//  - window coordinates: see toLlWindow;
//  - the triangles llvmpipe sets up: those of Mesa's draw module, clipped as
//    clipLikeDraw does and fanned as draw_pipe_clip.c emit_poly does,
//    (p[i-1], p[i], p[0]); a clockwise one (in llvmpipe's y-down space) is
//    set up as (v1, v0, v2) (lp_setup_tri.c triangle_both/triangle_cw, last
//    vertex provoking);
//  - the plane: lp_state_setup.c init_args/calc_coef4, single precision,
//    unfused: ooa = 1 / (dx01 * dy20 - dy01 * dx20),
//    dadx = da01 * (dy20 * ooa) - da20 * (dy01 * ooa),
//    dady = da20 * (dx01 * ooa) - da01 * (dx20 * ooa),
//    a0 = z0 - (dadx * (x0 - 0.5) + dady * (y0 - 0.5));
//  - per pixel: lp_bld_interp.c attribs_update_simple, a0 + x * dadx +
//    y * dady as two fused lp_build_fmuladd (this CPU has FMA), x and y the
//    integer pixel corner in llvmpipe's space.
// A clipped triangle becomes several llvmpipe triangles whose fan differs
// from MPR's, so each pixel takes the plane of the one containing its centre.
struct LlvmpipeDepth {
  struct Triangle {
    float a0, dzdx, dzdy;
    std::array<LlWindow, 3> v;  // in the order set up, counter-clockwise in y-down space
    // init_args' terms every attribute's plane shares, and the vertices' 1/w
    // (the position's w as the draw module leaves it) and varyings, in the
    // order set up.
    float dy20ooa, dy01ooa, dx20ooa, dx01ooa, x0Center, y0Center;
    std::array<float, 3> oow;
    std::array<std::array<float, kVaryings>, 3> attr;
    // calc_coef4 of the values v0, v1, v2 at the vertices in set-up order.
    PlaneCoefficients plane(float v0, float v1, float v2) const;
    // lp_setup_tri.c calc_fixed_position: (v - 0.5) in 1/256 pixel, and the
    // edges' half-plane constants of do_triangle_ccw (fill rule included).
    std::array<std::int64_t, 3> fixedX, fixedY, c;
    bool ccwUp = true;  // counter-clockwise in GL's y-up window space (its facing)
    // Mesa's draw pipeline culls each triangle of a clipped fan before
    // llvmpipe sets it up (draw_pipe_validate.c builds clip -> cull, and
    // draw_pipe_cull.c cull_tri): det = ex fy - ey fx on the float window
    // positions, e = v0 - v2, f = v1 - v2, in the order draw emitted them;
    // det < 0 is counter-clockwise in GL's y-up window (llvmpipe's
    // fixed-point area is -det), 0 back-facing. A sliver's float det and
    // snapped area can have opposite signs: then culling either face drops
    // it (repro/draw_cull_sliver.gls).
    float drawDet = 0.0f;
    // Whether an edge's step, x[i] - x[i+1] or y[i] - y[i+1] in 1/256 pixel,
    // leaves llvmpipe's 32 bits once shifted by FIXED_ORDER (a vertex at
    // the clip-space origin, INT32_MIN): then its block rejects and
    // per-pixel tests are not covers()' exact test (LlvmpipeTileRaster
    // walks them).
    bool wrapsSteps = false;
    // Whether llvmpipe's rasterizer covers the pixel (x, yDown).
    bool covers(int x, int yDown) const;
  };

  WindowTransform window;
  const std::vector<ClipPlane>* userPlanes;
  std::vector<Triangle> triangles;
  // Whether draw's clipper cut the last triangle added (then its fan, not
  // MPR's triangle, is what llvmpipe rasterises: GLContext draws that fan).
  bool clipped = false;
  // The clipper's polygons, storage kept between the triangles of a draw.
  std::vector<DrawVertex> clipScratchIn = {}, clipScratchOut = {};

  // Adds the triangles draw and llvmpipe make of (a, b, c), given in the
  // order llvmpipe receives it.
  void add(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c);

  float at(int x, int yDown) const { return planeAt(triangles.size() == 1 ? triangles[0] : containing(x, yDown), x, yDown); }
  static float planeAt(const Triangle& t, int x, int yDown) {
    return planeAt(t.a0, t.dzdx, t.dzdy, static_cast<float>(x), static_cast<float>(yDown));
  }
  static float planeAt(float a0, float dzdx, float dzdy, float x, float yDown) {
    return PlaneCoefficients{a0, dzdx, dzdy}.at(x, yDown);
  }

 private:
  // Sets up the triangle of the three vertices (clip position, varyings,
  // window position), in the order llvmpipe receives them.
  using Varyings = std::array<float, kVaryings>;
  void setUp(std::array<const Vec4*, 3> clip, std::array<const Varyings*, 3> attr, std::array<LlWindow, 3> p);

  // The triangle llvmpipe's fixed-point edges cover the pixel with (the fill
  // rule gives it to one of the fan); where a pixel MPR covers falls just
  // outside llvmpipe's polygon, the one whose edges are farthest outwards
  // from its centre.
  const Triangle& containing(int x, int yDown) const;
};

}  // namespace mpr
