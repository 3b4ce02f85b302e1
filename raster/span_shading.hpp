#pragma once
// The per-pixel half of drawing a triangle, a row span at a time: the set-up
// (TriangleShading) is computed once per triangle by GLContext, and
// shadeSpan turns up to FragmentSpan::kCapacity covered pixels of one row
// into fragments (depth and colour) with the same arithmetic, pixel for
// pixel, that a per-pixel loop would do (softpipe's sp_setup.c: coefficients
// once per triangle, then spans). The loops run over arrays so the compiler
// can do several pixels per instruction; every operation is exact IEEE, so
// the bits do not depend on how many it does at once.
#include <array>
#include <cstdint>

#include "framebuffer/fragment_pipeline.hpp"
#include "raster/fog.hpp"
#include "raster/llvmpipe_depth.hpp"
#include "raster/triangle_rasterizer.hpp"

namespace mpr {

// A triangle's channels as llvmpipe interpolates them (lp_state_setup.c
// emit_tri_coef and apply_perspective_corr, lp_bld_interp.c
// attribs_update_simple): the colours (perspective, or the provoking
// vertex's when flat-shaded) and the fog coordinate (perspective) each set
// up as a plane of value / w, and the position's 1 / w as a plane; per
// pixel, (plane at the pixel) * (1 / (1/w plane at the pixel)), in single
// precision, every plane evaluated with fused multiply-adds.
struct ChannelPlanes {
  PlaneCoefficients oow;  // the position's 1 / w
  std::array<PlaneCoefficients, 5> channel{};
  // A channel whose value is the same at every pixel (flat, or both its
  // plane and the 1 / w plane without gradient): that value.
  std::array<bool, 5> uniform{};
  std::array<float, 5> uniformValue{};
  bool allUniform = false;  // every channel used (four, five with fog)
};

// Sets up `out` from one of llvmpipe's triangles: the colour set at
// colorOffset (front 0, back 4) and the fog coordinate; `flat` for
// GL_FLAT (the colours constant, the fog coordinate still interpolated).
void setUpChannelPlanes(const LlvmpipeDepth::Triangle& t, int colorOffset, bool flat, bool fog, ChannelPlanes& out);

struct TriangleShading {
  // The fields a triangle of llvmpipe's planes reads come first, in the
  // first lines of the set-up (a row thread reads them on another core from
  // the one that wrote them); the exact weights, read only for MPR's own
  // colours and the window map, after them.

  // Depth: none (0), the window map's projective weights (mapZ, mapInvQ),
  // or llvmpipe's planes (one plane evaluated directly; several chosen per
  // pixel by LlvmpipeDepth::at).
  enum class Depth : std::uint8_t { None, WindowMap, OnePlane, Planes } depth = Depth::None;
  bool color = false;  // the fragments' colours are computed
  // The colour is one value that every fragment takes as it is (flat
  // shading, or Mesa's current colour): attr[0][0..3], not interpolated.
  bool uniformColor = false;
  // Where llvmpipe draws the triangle as one (not clipped, no window map):
  // its own interpolation, which replaces the exact weights below but fog.
  bool llvmpipeColor = false;
  float a0 = 0.0f, dzdx = 0.0f, dzdy = 0.0f;  // Depth::OnePlane
  float depthMax = 0.0f;
  int fbHeight = 0;
  const LlvmpipeDepth* planes = nullptr;  // Depth::Planes
  const FogState* fog = nullptr;          // null when fog is off
  ChannelPlanes channels;                 // llvmpipeColor

  // Barycentric weights of a pixel centre: from the snapped edge functions
  // (w_i / snappedArea) where the unsnapped triangle is degenerate, else
  // from the unsnapped window positions (exact* below).
  bool useSnapped = false;
  double snappedArea = 1.0;
  double xWin0 = 0.0, yWin0 = 0.0, ex1 = 0.0, ey1 = 0.0, ex2 = 0.0, ey2 = 0.0, exactArea = 1.0;
  std::array<double, 3> mapZ{}, mapInvQ{};  // Depth::WindowMap

  // Colour: perspective-correct interpolation of attr / w; attr[i] holds
  // the vertex's RGBA (front or back set) and its fog coordinate.
  std::array<double, 3> invW{};
  std::array<std::array<float, 5>, 3> attr{};
  std::array<bool, 5> constant{};  // attr[0][i], attr[1][i], attr[2][i] the same float (bit for bit)
  // Every channel used is constant, the weights come from the unsnapped
  // positions with no window map, and 1/w varies by at most 2^20 over the
  // vertices: a span may then take the colour without exact weights
  // (flatColorHolds in span_shading.cpp); reciprocalArea = 1 / exactArea.
  bool flatColor = false;
  double reciprocalArea = 0.0;
};

// A triangle Mesa's draw module clips, drawn as llvmpipe's fan of it
// (DrawStage::rasterizeLlvmpipeFan): depth and colour from the planes of
// the fan triangle, set up on the vertices draw's clipper made.
struct FanShading {
  bool depth = false;  // llvmpipe's plane of the fan triangle (a0, dzdx, dzdy)
  float a0 = 0.0f, dzdx = 0.0f, dzdy = 0.0f;
  float depthMax = 0.0f;
  int fbHeight = 0;
  bool color = false;
  ChannelPlanes planes;
  const FogState* fog = nullptr;
};

// Fills out.count pixels from (out.x, out.y) as rasterizeLlvmpipeFan's
// per-pixel loop does.
void shadeFanSpan(const FanShading& t, FragmentSpan& out);

// The channels a triangle's fragments interpolate, per vertex: the colour
// set at `colorOffset` (front 0, back 4) and the fog coordinate; and which
// of them are the same float, bit for bit, at the three vertices.
void vertexChannels(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int colorOffset,
                    std::array<std::array<float, 5>, 3>& attr, std::array<bool, 5>& constant);

// Sets flatColor and reciprocalArea from the fields above.
void decideFlatColor(TriangleShading& t);

// Fills out.depth, out.color and out.alpha for out.count pixels starting at
// (out.x, out.y); w and stepX are the covered span's edge functions at out.x
// (CoveredSpan). Without depth the fragments' depth is 0, without colour
// their colour and alpha are 0.
void shadeSpan(const TriangleShading& t, const std::array<std::int64_t, 3>& w,
               const std::array<std::int64_t, 3>& stepX, FragmentSpan& out);

}  // namespace mpr
