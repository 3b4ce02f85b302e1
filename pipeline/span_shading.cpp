#include "pipeline/span_shading.hpp"

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

// The colour of a fragment from its interpolated channels: fog, the clamp
// (glm::clamp(c, 0, 1): std::min and std::max, NaN kept), the bytes.
[[gnu::always_inline]] inline void finishColor(const FogState* fog, float (&channel)[5][kN], int n, FragmentSpan& out) {
  if (fog) {
    // Per fragment (fogFactor may call exp); GL_FASTEST takes the coordinate as the factor.
    for (int k = 0; k < n; ++k) {
      const float factor = fog->perFragment ? fogFactor(*fog, channel[4][k]) : std::clamp(channel[4][k], 0.0f, 1.0f);
      const Vec4 fogged =
          applyFog(*fog, factor, Vec4(channel[0][k], channel[1][k], channel[2][k], channel[3][k]));
      channel[0][k] = fogged.r;
      channel[1][k] = fogged.g;
      channel[2][k] = fogged.b;
      channel[3][k] = fogged.a;
    }
  }
  // Clamped as glm::clamp(c, 0, 1) (NaN kept), then converted.
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < n; ++k) channel[i][k] = std::min(std::max(channel[i][k], 0.0f), 1.0f);
  // Packed four bytes to a word (Rgba8's order in memory), so the loop stays on lanes.
  constexpr bool kLittle = std::endian::native == std::endian::little;
  alignas(64) std::uint32_t bytes[4][kN], packed[kN];
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < n; ++k) bytes[i][k] = unorm8(channel[i][k]);
  for (int k = 0; k < n; ++k) {
    packed[k] = bytes[0][k] << (kLittle ? 0 : 24) | bytes[1][k] << (kLittle ? 8 : 16) |
                bytes[2][k] << (kLittle ? 16 : 8) | bytes[3][k] << (kLittle ? 24 : 0);
    out.alpha[k] = channel[3][k];
  }
  // A loop, not a memcpy of n words (a library call per span; see CMakeLists.txt).
  for (int k = 0; k < n; ++k) std::memcpy(&out.color[k], &packed[k], sizeof(Rgba8));
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

// The channels of out.count pixels from (out.x, out.y) as llvmpipe's
// fragment shader interpolates them (ChannelPlanes), then finished.
[[gnu::always_inline]] inline void llvmpipeColor(const ChannelPlanes& p, int fbHeight, const FogState* fog,
                                                 FragmentSpan& out) {
  const int n = paddedLanes(out.count);
  const int channels = fog ? 5 : 4;
  alignas(64) float channel[5][kN];
  if (p.allUniform) {
    for (int i = 0; i < channels; ++i)
      for (int k = 0; k < n; ++k) channel[i][k] = p.uniformValue[i];
    return finishColor(fog, channel, n, out);
  }
  const float yDown = static_cast<float>(fbHeight - 1 - out.y);
  alignas(64) float x[kN], oow[kN];
  for (int k = 0; k < n; ++k) x[k] = static_cast<float>(out.x + k);
  // lp_build_rcp: a division, not RCPPS.
  for (int k = 0; k < n; ++k) oow[k] = 1.0f / p.oow.at(x[k], yDown);
  for (int i = 0; i < channels; ++i) {
    if (p.uniform[i]) {
      for (int k = 0; k < n; ++k) channel[i][k] = p.uniformValue[i];
      continue;
    }
    const PlaneCoefficients c = p.channel[i];
    for (int k = 0; k < n; ++k) channel[i][k] = c.at(x[k], yDown) * oow[k];
  }
  finishColor(fog, channel, n, out);
}

}  // namespace

void setUpChannelPlanes(const LlvmpipeDepth::Triangle& t, int colorOffset, bool flat, bool fog, ChannelPlanes& out) {
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

MPR_CPU_CLONES
void shadeSpan(const TriangleShading& t, const std::array<std::int64_t, 3>& w, const std::array<std::int64_t, 3>& stepX,
               FragmentSpan& out) {
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
  if (t.llvmpipeColor) return llvmpipeColor(t.channels, t.fbHeight, t.fog, out);
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
  finishColor(t.fog, channel, n, out);
}

MPR_CPU_CLONES
void shadeFanSpan(const FanShading& t, FragmentSpan& out) {
  const int n = paddedLanes(out.count);
  alignas(64) float z[kN];
  if (t.depth) {
    const float yDown = static_cast<float>(t.fbHeight - 1 - out.y);
    for (int k = 0; k < n; ++k) z[k] = LlvmpipeDepth::planeAt(t.a0, t.dzdx, t.dzdy, static_cast<float>(out.x + k), yDown);
  } else {
    for (int k = 0; k < n; ++k) z[k] = 0.0f;
  }
  storeDepths(z, n, t.depthMax, out);
  if (!t.color) return noColor(out);
  llvmpipeColor(t.planes, t.fbHeight, t.fog, out);
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
