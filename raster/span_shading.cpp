#include "raster/span_shading.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <cmath>

#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

constexpr int kN = FragmentSpan::kCapacity;

// Loops whose inputs are defined at every lane run over paddedLanes
// (fragment_pipeline.hpp); lanes past the count compute values nothing
// reads. A reduction over the span, or a loop on planes valid only within
// it, keeps the count.

// floatToUnorm8 (fragment_ops.hpp) on a clamped channel, written branch-free.
[[gnu::always_inline]] inline std::uint32_t unorm8(float c) {
  // c is in [0, 1] or NaN: NaN and 0 give 0, 1 gives 255 (255 * 1 rounds
  // to itself); below 255, adding and taking off 2^23 rounds to nearest even.
  const float positive = std::max(0.0f, c);  // (0 < c) ? c : 0
  return static_cast<std::uint32_t>(static_cast<std::int32_t>((positive * 255.0f + 8388608.0f) - 8388608.0f));
}

// The span loops below run a block of kBlock lanes at a time with the
// block's width a constant, every stage of a block before the next block:
// its values stay in vector registers, and a span of a few pixels (most
// spans of a scene's triangles) costs one block, not one pass per stage,
// each with the set-up and remainder a loop of unknown length gets.
constexpr int kBlock = 8;
static_assert(kN % kBlock == 0);

// The depths as llvmpipe quantises them to a unorm buffer: std::clamp(z, 0,
// 1) (NaN, -0 and below to 0, 1 and above to 1) times the float maximum, a
// single-precision product, rounded to nearest even.
[[gnu::always_inline]] inline void storeDepths(const float (&z)[kN], int lanes, float depthMax, FragmentSpan& out) {
  for (int k = 0; k < lanes; ++k) out.depth[k] = windowDepthToWord(z[k], depthMax);
}

// Fragments of a state that writes no colour carry none.
[[gnu::always_inline]] inline void noColor(FragmentSpan& out) {
  for (int k = 0; k < paddedLanes(out.count); ++k) {
    out.color[k] = Rgba8{0, 0, 0, 0};
    out.alpha[k] = 0.0f;
  }
}

// The colours and alphas of a block of fragments from their interpolated
// channels: fog, the clamp (glm::clamp(c, 0, 1): std::min and
// std::max, NaN kept), the bytes.
[[gnu::always_inline]] inline void finishBlock(const FogState* fog, float (&channel)[5][kBlock], Rgba8* color,
                                               float* alpha) {
  if (fog) {
    // Per fragment (fogFactor may call exp); GL_FASTEST takes the coordinate as the factor.
    for (int j = 0; j < kBlock; ++j) {
      const float factor = fog->perFragment ? fogFactor(*fog, channel[4][j]) : std::clamp(channel[4][j], 0.0f, 1.0f);
      const Vec4 fogged = applyFog(*fog, factor, Vec4(channel[0][j], channel[1][j], channel[2][j], channel[3][j]));
      channel[0][j] = fogged.r;
      channel[1][j] = fogged.g;
      channel[2][j] = fogged.b;
      channel[3][j] = fogged.a;
    }
  }
  // Clamped as glm::clamp(c, 0, 1) (NaN kept), then converted and packed
  // four bytes to a word (Rgba8's order in memory).
  constexpr bool kLittle = std::endian::native == std::endian::little;
  for (int j = 0; j < kBlock; ++j) {
    float c[4];
    for (int i = 0; i < 4; ++i) c[i] = std::min(std::max(channel[i][j], 0.0f), 1.0f);
    const std::uint32_t packed = unorm8(c[0]) << (kLittle ? 0 : 24) | unorm8(c[1]) << (kLittle ? 8 : 16) |
                                 unorm8(c[2]) << (kLittle ? 16 : 8) | unorm8(c[3]) << (kLittle ? 24 : 0);
    alpha[j] = c[3];
    std::memcpy(&color[j], &packed, sizeof(Rgba8));
  }
}

// finishBlock over `lanes` (a multiple of kBlock) of whole-span channels.
[[gnu::always_inline]] inline void finishColor(const FogState* fog, const float (&channel)[5][kN], int lanes,
                                               FragmentSpan& out) {
  for (int base = 0; base < lanes; base += kBlock) {
    float block[5][kBlock];
    for (int i = 0; i < (fog ? 5 : 4); ++i)
      for (int j = 0; j < kBlock; ++j) block[i][j] = channel[i][base + j];
    finishBlock(fog, block, &out.color[base], &out.alpha[base]);
  }
}

// Whether weights w0, w1, w2 (summing to `sum`, or its magnitude) are
// conditioned well enough for a channel equal at the three vertices to
// interpolate to that float exactly: |w0|+|w1|+|w2| at most 2^20 times the
// sum (the rounding error is then under (5 * 2^20 + 2) 2^-53 < 2^-30 of the
// value, far inside the half ulp, 2^-25, that rounding to float needs), and
// between 2^-800 and 2^850, so that no product with a float attribute
// overflows or falls among the subnormals, where the relative bound fails.
[[gnu::always_inline]] inline std::uint32_t wellConditioned(double w0, double w1, double w2, double sum) {
  const double s = std::fabs(w0) + std::fabs(w1) + std::fabs(w2);
  return (s <= 0x1p20 * sum) & (s <= 0x1p850) & (s >= 0x1p-800);
}

// Whether a span of a flat-coloured triangle (TriangleShading::flatColor)
// may take the vertices' colour without its exact weights. The weights
// here are approximate: N * (1 / A) instead of N / A, each within 3 ulp of
// the exact path's, so every p_i within 11 u rho S of it (u = 2^-53, rho =
// the 1/w spread, at most 2^20; S = |p0|+|p1|+|p2|). Where this span's
// approximate condition number is at most 2^20, the exact path's is under
// 2^21, and there (shadeSpan's bound, (5 kappa + 2) u < 2^-29) each channel
// interpolates to the vertices' float exactly.
[[gnu::always_inline]] inline bool flatColorHolds(const TriangleShading& t, const FragmentSpan& out) {
  const double py = out.y + 0.5 - t.yWin0;
  const double pyEx2 = py * t.ex2, pyEx1 = py * t.ex1;
  std::uint32_t holds = 1;
  for (int k = 0; k < out.count; ++k) {
    const double px = static_cast<double>(out.x + k) + 0.5 - t.xWin0;
    const double b1 = (px * t.ey2 - pyEx2) * t.reciprocalArea, b2 = (pyEx1 - px * t.ey1) * t.reciprocalArea;
    const double p0 = (1.0 - b1 - b2) * t.invW[0], p1 = b1 * t.invW[1], p2 = b2 * t.invW[2];
    holds &= wellConditioned(p0, p1, p2, p0 + p1 + p2);
  }
  return holds != 0;
}

// Where llvmpipeBlocks takes the fragments' depth from: none (0), one
// plane of llvmpipe's, or the span as it is (stored before).
enum class BlockDepth { Zero, Plane, Stored };

// Depth (BlockDepth) and the channels as llvmpipe's fragment shader
// interpolates them (ChannelPlanes), then finished, for out.count pixels
// from (out.x, out.y), a block at a time. `planes` is null where the
// fragments carry no colour.
[[gnu::always_inline]] inline void llvmpipeBlocks(BlockDepth depth, float a0, float dzdx, float dzdy, float depthMax,
                                                  const ChannelPlanes* planes, int fbHeight, const FogState* fog,
                                                  FragmentSpan& out) {
  const int lanes = paddedLanes(out.count);
  const float yDown = static_cast<float>(fbHeight - 1 - out.y);
  // Every channel the same at every pixel: finished once (fog included,
  // its coordinate uniform too), the same word and alpha for each fragment.
  std::uint32_t uniformWords[kBlock] = {};
  float uniformAlphas[kBlock] = {};
  static_assert(sizeof uniformWords == kBlock * sizeof(Rgba8));
  if (planes && planes->allUniform) {
    float channel[5][kBlock];
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < kBlock; ++j) channel[i][j] = planes->uniformValue[i];
    Rgba8 colors[kBlock];
    finishBlock(fog, channel, colors, uniformAlphas);
    std::memcpy(uniformWords, colors, sizeof uniformWords);
  }
  // The block's pixel columns and, unless stored before, depths.
  const auto columnsAndDepth = [&](int base, float (&x)[kBlock]) {
    for (int j = 0; j < kBlock; ++j) x[j] = static_cast<float>(out.x + base + j);
    if (depth == BlockDepth::Plane)
      for (int j = 0; j < kBlock; ++j)
        out.depth[base + j] = windowDepthToWord(LlvmpipeDepth::planeAt(a0, dzdx, dzdy, x[j], yDown), depthMax);
    else if (depth == BlockDepth::Zero)
      for (int j = 0; j < kBlock; ++j) out.depth[base + j] = 0u;
  };
  if (!planes || planes->allUniform) {
    // No colour (words of zero), or one finished colour for every
    // fragment: a block's words and alphas stored whole.
    for (int base = 0; base < lanes; base += kBlock) {
      float x[kBlock];
      columnsAndDepth(base, x);
      std::memcpy(&out.color[base], uniformWords, sizeof uniformWords);
      std::memcpy(&out.alpha[base], uniformAlphas, sizeof uniformAlphas);
    }
    return;
  }
  for (int base = 0; base < lanes; base += kBlock) {
    float x[kBlock];
    columnsAndDepth(base, x);
    const ChannelPlanes& p = *planes;
    // lp_build_rcp: a division, not RCPPS.
    float oow[kBlock], channel[5][kBlock];
    for (int j = 0; j < kBlock; ++j) oow[j] = 1.0f / p.oow.at(x[j], yDown);
    // All five channels (the fog coordinate's plane is set up with or
    // without fog): a count known here unrolls the loop.
#pragma GCC unroll 5
    for (int i = 0; i < 5; ++i) {
      const PlaneCoefficients c = p.channel[i];
      for (int j = 0; j < kBlock; ++j) channel[i][j] = p.uniform[i] ? p.uniformValue[i] : c.at(x[j], yDown) * oow[j];
    }
    finishBlock(fog, channel, &out.color[base], &out.alpha[base]);
  }
}

}  // namespace

MPR_CPU_CLONES void setUpChannelPlanes(const LlvmpipeDepth::Triangle& t, int colorOffset, bool flat, bool fog, ChannelPlanes& out) {
  out.oow = t.plane(t.oow[0], t.oow[1], t.oow[2]);
  const bool oowUniform = out.oow.dadx == 0.0f && out.oow.dady == 0.0f;
  const int channels = fog ? 5 : 4;
  out.allUniform = true;
  for (int i = 0; i < 5; ++i) {
    const int source = i < 4 ? colorOffset + i : 8;
    if (i < 4 && flat) {
      // LP_INTERP_CONSTANT: the provoking vertex's value (GLContext has
      // given it to all three).
      out.channel[static_cast<std::size_t>(i)] = {t.attr[2][static_cast<std::size_t>(source)], 0.0f, 0.0f};
      out.uniform[static_cast<std::size_t>(i)] = true;
      out.uniformValue[static_cast<std::size_t>(i)] = t.attr[2][static_cast<std::size_t>(source)];
      continue;
    }
    // apply_perspective_corr: the values times 1 / w, then calc_coef4.
    const PlaneCoefficients c = t.plane(t.attr[0][static_cast<std::size_t>(source)] * t.oow[0],
                                        t.attr[1][static_cast<std::size_t>(source)] * t.oow[1],
                                        t.attr[2][static_cast<std::size_t>(source)] * t.oow[2]);
    out.channel[static_cast<std::size_t>(i)] = c;
    // Without gradients, fma(0, x, a0) is a0 (but for zero's sign, which
    // nothing downstream tells apart) at every pixel.
    const bool uniform = oowUniform && c.dadx == 0.0f && c.dady == 0.0f;
    out.uniform[static_cast<std::size_t>(i)] = uniform;
    out.uniformValue[static_cast<std::size_t>(i)] = uniform ? c.a0 * (1.0f / out.oow.a0) : 0.0f;
    if (i < channels) out.allUniform = out.allUniform && uniform;
  }
}

namespace {

// shadeSpan where the weights or several depth planes are needed (a
// triangle MPR's clipper cut, or under a window map): its own function, so
// that the common case pays nothing for its arrays.
MPR_CPU_CLONES [[gnu::noinline]]
void shadeExactSpan(const TriangleShading& t, const std::array<std::int64_t, 3>& w,
                    const std::array<std::int64_t, 3>& stepX, FragmentSpan& out) {
  const int n = out.count;
  const bool flat = t.flatColor && flatColorHolds(t, out);
  // Barycentric weights of the pixel centres (colour and the window map's
  // depth need them; llvmpipe's planes and a flat colour do not).
  alignas(64) double b0[kN], b1[kN], b2[kN];
  const bool exactColor = t.color && !t.llvmpipeColor && !flat;
  if (!exactColor && t.depth != TriangleShading::Depth::WindowMap) {
  } else if (t.useSnapped) {
    for (int k = 0; k < n; ++k) {
      b0[k] = static_cast<double>(w[0] + k * stepX[0]) / t.snappedArea;
      b1[k] = static_cast<double>(w[1] + k * stepX[1]) / t.snappedArea;
      b2[k] = static_cast<double>(w[2] + k * stepX[2]) / t.snappedArea;
    }
  } else {
    const double py = out.y + 0.5 - t.yWin0;
    const double pyEx2 = py * t.ex2, pyEx1 = py * t.ex1;
    for (int k = 0; k < n; ++k) {
      const double px = static_cast<double>(out.x + k) + 0.5 - t.xWin0;
      b1[k] = (px * t.ey2 - pyEx2) / t.exactArea;
      b2[k] = (pyEx1 - px * t.ey1) / t.exactArea;
      b0[k] = 1.0 - b1[k] - b2[k];
    }
  }

  // Depth: llvmpipe's plane evaluated as its fragment shader does, then
  // quantised (storeDepths).
  alignas(64) float z[kN];
  const int lanes = paddedLanes(n);
  int depthLanes = lanes;  // the planes below are defined at every lane
  switch (t.depth) {
    case TriangleShading::Depth::None:
      for (int k = 0; k < lanes; ++k) z[k] = 0.0f;
      break;
    case TriangleShading::Depth::WindowMap:
      for (int k = 0; k < n; ++k) {
        const double q0 = b0[k] * t.mapInvQ[0], q1 = b1[k] * t.mapInvQ[1], q2 = b2[k] * t.mapInvQ[2];
        z[k] = static_cast<float>((q0 * t.mapZ[0] + q1 * t.mapZ[1] + q2 * t.mapZ[2]) / (q0 + q1 + q2));
      }
      depthLanes = n;
      break;
    case TriangleShading::Depth::OnePlane: {
      const float yDown = static_cast<float>(t.fbHeight - 1 - out.y);
      for (int k = 0; k < lanes; ++k) z[k] = LlvmpipeDepth::planeAt(t.a0, t.dzdx, t.dzdy, static_cast<float>(out.x + k), yDown);
      break;
    }
    case TriangleShading::Depth::Planes:
      for (int k = 0; k < n; ++k) z[k] = t.planes->at(out.x + k, t.fbHeight - 1 - out.y);
      depthLanes = n;
      break;
  }
  storeDepths(z, depthLanes, t.depthMax, out);
  if (!t.color) return noColor(out);
  // llvmpipe's colour planes with several depth planes (a clipped polygon's).
  if (t.llvmpipeColor)
    return llvmpipeBlocks(BlockDepth::Stored, 0.0f, 0.0f, 0.0f, 0.0f, &t.channels, t.fbHeight, t.fog, out);
  // Perspective-correct: interpolate attr/w and 1/w.
  alignas(64) float channel[5][kN];
  const int channels = t.fog ? 5 : 4;
  if (flat) {
    for (int i = 0; i < channels; ++i)
      for (int k = 0; k < lanes; ++k) channel[i][k] = t.attr[0][i];
    return finishColor(t.fog, channel, lanes, out);
  }
  // Where every pixel's weights are well conditioned (wellConditioned), a
  // channel equal at the three vertices is copied, not computed: the
  // interpolation would give that float. Zero's sign may differ; nothing
  // downstream tells +0 from -0 (clamp, conversion, fog, the alpha test).
  std::uint32_t allWellConditioned = 1;
  for (int k = 0; k < n; ++k) {
    const double p0 = b0[k] * t.invW[0], p1 = b1[k] * t.invW[1], p2 = b2[k] * t.invW[2];
    b0[k] = p0;
    b1[k] = p1;
    b2[k] = p2;
    allWellConditioned &= wellConditioned(p0, p1, p2, p0 + p1 + p2);
  }
  alignas(64) double inv[kN];
  bool invDone = false;
  for (int i = 0; i < channels; ++i) {
    if ((i < 4 && t.uniformColor) || (t.constant[i] && allWellConditioned)) {
      for (int k = 0; k < n; ++k) channel[i][k] = t.attr[0][i];
      continue;
    }
    if (!invDone) {
      for (int k = 0; k < n; ++k) inv[k] = 1.0 / (b0[k] + b1[k] + b2[k]);
      invDone = true;
    }
    const double a0 = t.attr[0][i], a1 = t.attr[1][i], a2 = t.attr[2][i];
    for (int k = 0; k < n; ++k) channel[i][k] = static_cast<float>((b0[k] * a0 + b1[k] * a1 + b2[k] * a2) * inv[k]);
  }
  // The lanes past the count are finished too (whole blocks), from zeros.
  for (int i = 0; i < channels; ++i)
    for (int k = n; k < lanes; ++k) channel[i][k] = 0.0f;
  finishColor(t.fog, channel, lanes, out);
}

}  // namespace

MPR_CPU_CLONES
void shadeSpan(const TriangleShading& t, const std::array<std::int64_t, 3>& w, const std::array<std::int64_t, 3>& stepX,
               FragmentSpan& out) {
  // llvmpipe's planes, or no colour, with at most one depth plane: a block at a time.
  if ((!t.color || t.llvmpipeColor) &&
      (t.depth == TriangleShading::Depth::None || t.depth == TriangleShading::Depth::OnePlane))
    return llvmpipeBlocks(t.depth == TriangleShading::Depth::OnePlane ? BlockDepth::Plane : BlockDepth::Zero, t.a0,
                          t.dzdx, t.dzdy, t.depthMax, t.color ? &t.channels : nullptr, t.fbHeight, t.fog, out);
  shadeExactSpan(t, w, stepX, out);
}

MPR_CPU_CLONES
void shadeFanSpan(const FanShading& t, FragmentSpan& out) {
  llvmpipeBlocks(t.depth ? BlockDepth::Plane : BlockDepth::Zero, t.a0, t.dzdx, t.dzdy, t.depthMax,
                 t.color ? &t.planes : nullptr, t.fbHeight, t.fog, out);
}

void decideFlatColor(TriangleShading& t) {
  const int channels = t.fog ? 5 : 4;
  bool constant = t.color && !t.useSnapped && t.depth != TriangleShading::Depth::WindowMap;
  for (int i = 0; i < channels; ++i) constant = constant && t.constant[i];
  const double lo = std::min({t.invW[0], t.invW[1], t.invW[2]}), hi = std::max({t.invW[0], t.invW[1], t.invW[2]});
  t.flatColor = constant && lo > 0.0 && std::isfinite(hi) && hi <= 0x1p20 * lo;
  t.reciprocalArea = 1.0 / t.exactArea;
}

void vertexChannels(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int colorOffset,
                    std::array<std::array<float, 5>, 3>& attr, std::array<bool, 5>& constant) {
  const ClipVertex* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    for (int ch = 0; ch < 4; ++ch) attr[i][ch] = v[i]->attr[colorOffset + ch];
    attr[i][4] = v[i]->attr[8];
  }
  for (int ch = 0; ch < 5; ++ch)
    constant[ch] = std::bit_cast<std::uint32_t>(attr[0][ch]) == std::bit_cast<std::uint32_t>(attr[1][ch]) &&
                   std::bit_cast<std::uint32_t>(attr[0][ch]) == std::bit_cast<std::uint32_t>(attr[2][ch]);
}

}  // namespace mpr
