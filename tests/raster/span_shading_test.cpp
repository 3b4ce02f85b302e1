// shadeSpan and shadeFanSpan against the per-pixel arithmetic they replace
// (the draw path's per-pixel loops before spans, written out here pixel by
// pixel with libm's nearbyint): every depth, colour byte and alpha bit for
// bit, on random triangles that include slivers, wild perspective (1/w over
// eight decades), channels equal at the three vertices (the copy the
// condition number allows) and not, flat-coloured triangles (their colour
// taken without exact weights), fog of every mode, and every depth kind;
// and llvmpipe's interpolation (ChannelPlanes) against its arithmetic
// written out per pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

#include "framebuffer/fragment_ops.hpp"
#include "raster/span_shading.hpp"

namespace mpr {
namespace {

struct Pixel {
  std::uint32_t depth;
  Rgba8 color;
  float alpha;
};

// floatToUnorm8 as it was, through libm's nearbyint.
std::uint8_t floatToUnorm8Reference(float c) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::nearbyint(c * 255.0f));
}

// The fragment's colour as the per-pixel loop made it (shadeColor then).
void referenceColor(const FogState* fog, Vec4 color, float fogCoord, Pixel& p) {
  if (fog) {
    const float factor = fog->perFragment ? fogFactor(*fog, fogCoord) : std::clamp(fogCoord, 0.0f, 1.0f);
    color = applyFog(*fog, factor, color);
  }
  auto clamp01 = [](float v) { return std::min(std::max(v, 0.0f), 1.0f); };
  color = Vec4(clamp01(color.r), clamp01(color.g), clamp01(color.b), clamp01(color.a));
  p.color = {floatToUnorm8Reference(color.r), floatToUnorm8Reference(color.g), floatToUnorm8Reference(color.b),
             floatToUnorm8Reference(color.a)};
  p.alpha = color.a;
}

std::uint32_t referenceDepth(float z, float depthMax) {
  z = std::clamp(z, 0.0f, 1.0f);
  return static_cast<std::uint32_t>(std::nearbyint(z * depthMax));
}

Pixel referencePixel(const TriangleShading& t, int x, int y, const std::array<std::int64_t, 3>& w) {
  double b0, b1, b2;
  if (t.useSnapped) {
    b0 = static_cast<double>(w[0]) / t.snappedArea;
    b1 = static_cast<double>(w[1]) / t.snappedArea;
    b2 = static_cast<double>(w[2]) / t.snappedArea;
  } else {
    const double px = x + 0.5 - t.xWin0, py = y + 0.5 - t.yWin0;
    b1 = (px * t.ey2 - py * t.ex2) / t.exactArea;
    b2 = (py * t.ex1 - px * t.ey1) / t.exactArea;
    b0 = 1.0 - b1 - b2;
  }
  Pixel p{0, Rgba8{0, 0, 0, 0}, 0.0f};
  if (t.depth == TriangleShading::Depth::WindowMap) {
    const double q0 = b0 * t.mapInvQ[0], q1 = b1 * t.mapInvQ[1], q2 = b2 * t.mapInvQ[2];
    p.depth = referenceDepth(static_cast<float>((q0 * t.mapZ[0] + q1 * t.mapZ[1] + q2 * t.mapZ[2]) / (q0 + q1 + q2)),
                             t.depthMax);
  } else if (t.depth == TriangleShading::Depth::OnePlane) {
    const float z = std::fma(t.dzdy, static_cast<float>(t.fbHeight - 1 - y), std::fma(t.dzdx, static_cast<float>(x), t.a0));
    p.depth = referenceDepth(z, t.depthMax);
  }
  if (t.color) {
    const double p0 = b0 * t.invW[0], p1 = b1 * t.invW[1], p2 = b2 * t.invW[2];
    const double inv = 1.0 / (p0 + p1 + p2);
    auto interp = [&](int i) {
      return static_cast<float>((p0 * t.attr[0][i] + p1 * t.attr[1][i] + p2 * t.attr[2][i]) * inv);
    };
    referenceColor(t.fog, Vec4(interp(0), interp(1), interp(2), interp(3)), t.fog ? interp(4) : 0.0f, p);
  }
  return p;
}

// llvmpipe's arithmetic written out per pixel from lp_state_setup.c and
// lp_bld_interp.c, apart from setUpChannelPlanes: calc_coef4 on the set-up
// terms, each channel value / w, the plane and 1 / w's plane at the pixel
// with fused multiply-adds, then the product with the reciprocal.
float referenceLlvmpipeChannel(const LlvmpipeDepth::Triangle& t, int source, bool flat, int x, int yDown) {
  if (flat) return t.attr[2][static_cast<std::size_t>(source)];
  auto coef = [&](float v0, float v1, float v2, float& a0, float& dadx, float& dady) {
    const float da01 = v0 - v1, da20 = v2 - v0;
    dadx = da01 * t.dy20ooa - da20 * t.dy01ooa;
    dady = da20 * t.dx01ooa - da01 * t.dx20ooa;
    a0 = v0 - (dadx * t.x0Center + dady * t.y0Center);
  };
  float w0, wdx, wdy, a0, adx, ady;
  coef(t.oow[0], t.oow[1], t.oow[2], w0, wdx, wdy);
  coef(t.attr[0][static_cast<std::size_t>(source)] * t.oow[0], t.attr[1][static_cast<std::size_t>(source)] * t.oow[1],
       t.attr[2][static_cast<std::size_t>(source)] * t.oow[2], a0, adx, ady);
  const float fx = static_cast<float>(x), fy = static_cast<float>(yDown);
  const float w = std::fma(wdy, fy, std::fma(wdx, fx, w0));
  return std::fma(ady, fy, std::fma(adx, fx, a0)) * (1.0f / w);
}

Pixel referenceFanPixel(const FanShading& s, const LlvmpipeDepth::Triangle& t, int colorOffset, bool flat, int x, int y) {
  Pixel p{0, Rgba8{0, 0, 0, 0}, 0.0f};
  const int yDown = s.fbHeight - 1 - y;
  if (s.depth)
    p.depth = referenceDepth(std::fma(s.dzdy, static_cast<float>(yDown), std::fma(s.dzdx, static_cast<float>(x), s.a0)),
                             s.depthMax);
  if (!s.color) return p;
  auto channel = [&](int i) { return referenceLlvmpipeChannel(t, i < 4 ? colorOffset + i : 8, flat && i < 4, x, yDown); };
  referenceColor(s.fog, Vec4(channel(0), channel(1), channel(2), channel(3)), s.fog ? channel(4) : 0.0f, p);
  return p;
}

void expectSamePixel(const Pixel& want, const FragmentSpan& got, int k, const std::string& where) {
  ASSERT_EQ(got.depth[k], want.depth) << where;
  ASSERT_EQ(got.color[k], want.color) << where;
  // Alpha bit for bit, but for zero's sign: a copied channel of 0 is +0
  // where the weights would have made -0, and the alpha test (the only
  // reader of a fragment's float alpha) converts both to 0.
  const bool bothNaN = std::isnan(got.alpha[k]) && std::isnan(want.alpha);
  const bool bothZero = got.alpha[k] == 0.0f && want.alpha == 0.0f;
  ASSERT_TRUE(bothNaN || bothZero || std::bit_cast<std::uint32_t>(got.alpha[k]) == std::bit_cast<std::uint32_t>(want.alpha))
      << where << ": alpha " << got.alpha[k] << " want " << want.alpha;
}

// Random channels: often equal at the three vertices (the copied case),
// sometimes 0, 1, out of [0, 1], or apart by an ulp.
void randomAttributes(std::mt19937& rng, std::array<std::array<float, 5>, 3>& attr, std::array<bool, 5>& constant) {
  std::uniform_real_distribution<float> value(-0.5f, 1.5f);
  for (int c = 0; c < 5; ++c) {
    const int kind = static_cast<int>(rng() % 6);
    const float v = kind == 4 ? 0.0f : kind == 5 ? 1.0f : value(rng);
    for (int i = 0; i < 3; ++i) attr[i][c] = kind < 2 ? value(rng) : v;
    if (kind == 1) attr[2][c] = std::nextafter(attr[0][c], 2.0f), attr[1][c] = attr[0][c];
    constant[c] = std::bit_cast<std::uint32_t>(attr[0][c]) == std::bit_cast<std::uint32_t>(attr[1][c]) &&
                  std::bit_cast<std::uint32_t>(attr[0][c]) == std::bit_cast<std::uint32_t>(attr[2][c]);
  }
}

FogState randomFog(std::mt19937& rng) {
  FogState f;
  f.enabled = true;
  f.mode = static_cast<FogMode>(rng() % 3);
  f.density = 0.5f + static_cast<float>(rng() % 100) / 50.0f;
  f.start = 0.1f;
  f.end = 2.0f;
  f.color = Vec4(0.25f, 0.5f, 0.75f, 1.0f);
  f.perFragment = rng() % 2 == 0;
  return f;
}

TEST(SpanShading, ShadeSpanIsThePerPixelArithmeticOnRandomTriangles) {
  std::mt19937 rng(1994);
  std::uniform_real_distribution<double> pos(0.0, 64.0), logW(-4.0, 4.0), unit(0.0, 1.0);
  FogState fog = randomFog(rng);
  int copied = 0, computed = 0, flat = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    TriangleShading t;
    double x[3], y[3];
    for (int i = 0; i < 3; ++i) x[i] = static_cast<float>(pos(rng)), y[i] = static_cast<float>(pos(rng));
    if (trial % 5 == 0) {  // a sliver: the third vertex almost on the line of the others
      const double s = unit(rng);
      x[2] = static_cast<float>(x[0] + s * (x[1] - x[0]) + 1e-3 * unit(rng));
      y[2] = static_cast<float>(y[0] + s * (y[1] - y[0]));
    }
    if (trial % 5 == 1) {  // a tiny sliver near the origin, its pixels far away: weights of 1e9 and more that cancel
      for (int i = 0; i < 2; ++i) x[i] = static_cast<float>(0.01 * unit(rng)), y[i] = static_cast<float>(0.01 * unit(rng));
      x[2] = static_cast<float>(0.5 * (x[0] + x[1]));
      y[2] = std::nextafter(static_cast<float>(0.5 * (y[0] + y[1])), 1.0f);
    }
    t.xWin0 = x[0];
    t.yWin0 = y[0];
    t.ex1 = x[1] - x[0], t.ey1 = y[1] - y[0], t.ex2 = x[2] - x[0], t.ey2 = y[2] - y[0];
    t.exactArea = t.ex1 * t.ey2 - t.ex2 * t.ey1;
    t.useSnapped = trial % 11 == 0 || !(std::fabs(t.exactArea) > 0.0);
    t.snappedArea = static_cast<double>(1 + rng() % 100000);
    for (int i = 0; i < 3; ++i) t.invW[i] = static_cast<double>(static_cast<float>(std::pow(10.0, logW(rng))));
    if (trial % 3 == 0) t.invW[1] = t.invW[2] = t.invW[0];
    t.depthMax = 16777215.0f;
    t.fbHeight = 64;
    t.depth = static_cast<TriangleShading::Depth>(rng() % 3);  // None, WindowMap, OnePlane
    t.a0 = static_cast<float>(unit(rng) * 1.2 - 0.1);
    t.dzdx = static_cast<float>((unit(rng) - 0.5) * 0.05);
    t.dzdy = static_cast<float>((unit(rng) - 0.5) * 0.05);
    for (int i = 0; i < 3; ++i) t.mapZ[i] = unit(rng), t.mapInvQ[i] = 0.5 + unit(rng);
    t.color = rng() % 8 != 0;
    randomAttributes(rng, t.attr, t.constant);
    if (trial % 4 == 0) {
      fog = randomFog(rng);
      t.fog = &fog;
    }
    decideFlatColor(t);
    flat += t.flatColor;
    FragmentSpan span;
    span.x = static_cast<int>(rng() % 64);
    span.y = static_cast<int>(rng() % 64);
    span.count = 1 + static_cast<int>(rng() % FragmentSpan::kCapacity);
    std::array<std::int64_t, 3> w, step;
    for (int i = 0; i < 3; ++i) w[i] = static_cast<std::int64_t>(rng() % 200000) - 50000, step[i] = static_cast<std::int64_t>(rng() % 512) - 256;
    shadeSpan(t, w, step, span);
    for (int k = 0; k < span.count; ++k) {
      const std::array<std::int64_t, 3> wk{w[0] + k * step[0], w[1] + k * step[1], w[2] + k * step[2]};
      const Pixel want = referencePixel(t, span.x + k, span.y, wk);
      expectSamePixel(want, span, k, "trial " + std::to_string(trial) + " pixel " + std::to_string(k));
    }
    const bool anyConstant = t.constant[0] || t.constant[1] || t.constant[2] || t.constant[3];
    (t.color && anyConstant ? copied : computed) += span.count;
  }
  EXPECT_GT(copied, 10000);  // the copied channels were exercised, not only the computed ones
  EXPECT_GT(flat, 300);      // and flat-coloured triangles
  EXPECT_GT(computed, 10000);
}

// Random clip-space triangles (w over six decades, some behind a view
// plane so that draw's clipper makes a fan with interpolated varyings),
// channels often equal at the vertices and w often equal (the uniform
// shortcut), flat and smooth, both colour sets, with and without fog.
TEST(SpanShading, ShadeFanSpanIsLlvmpipesPerPixelArithmeticOnRandomTriangles) {
  std::mt19937 rng(1997);
  std::uniform_real_distribution<double> coordinate(-1.3, 1.3), logW(-3.0, 3.0), unit(0.0, 1.0);
  FogState fog = randomFog(rng);
  const std::vector<ClipPlane> noUserPlanes;
  int uniformSpans = 0, perPixelSpans = 0, fanTriangles = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    LlvmpipeDepth setup{WindowTransform{32.0f, 32.0f, 32.0f, 32.0f, 0.5f, 0.5f, 64}, &noUserPlanes, {}};
    std::array<ClipVertex, 3> v;
    const float sharedW = static_cast<float>(std::pow(10.0, logW(rng)));
    std::array<std::array<float, 5>, 3> channels;
    std::array<bool, 5> constant;
    randomAttributes(rng, channels, constant);
    for (int i = 0; i < 3; ++i) {
      const float w = trial % 3 == 0 ? sharedW : static_cast<float>(std::pow(10.0, logW(rng)));
      v[i].clip = Vec4(static_cast<float>(coordinate(rng)) * w, static_cast<float>(coordinate(rng)) * w,
                       static_cast<float>(unit(rng) * 2.2 - 1.1) * w, w);
      for (int k = 0; k < 4; ++k) v[i].attr[k] = v[i].attr[4 + k] = channels[i][k];
      if (trial % 2 == 0) v[i].attr[5] = static_cast<float>(unit(rng));  // the back set differs
      v[i].attr[8] = channels[i][4];
    }
    setup.add(v[0], v[1], v[2]);
    if (setup.triangles.empty()) continue;
    fanTriangles += static_cast<int>(setup.triangles.size());
    const LlvmpipeDepth::Triangle& t = setup.triangles[rng() % setup.triangles.size()];
    FanShading s;
    s.depth = rng() % 4 != 0;
    s.a0 = t.a0;
    s.dzdx = t.dzdx;
    s.dzdy = t.dzdy;
    s.depthMax = 16777215.0f;
    s.fbHeight = 64;
    s.color = rng() % 8 != 0;
    if (trial % 4 == 0) {
      fog = randomFog(rng);
      s.fog = &fog;
    }
    const bool flat = trial % 5 == 0;
    const int colorOffset = trial % 2 == 0 ? 4 : 0;
    setUpChannelPlanes(t, colorOffset, flat, s.fog != nullptr, s.planes);
    (s.planes.allUniform ? uniformSpans : perPixelSpans) += s.color;
    FragmentSpan span;
    span.x = static_cast<int>(rng() % 64);
    span.y = static_cast<int>(rng() % 64);
    span.count = 1 + static_cast<int>(rng() % FragmentSpan::kCapacity);
    shadeFanSpan(s, span);
    for (int k = 0; k < span.count; ++k) {
      const Pixel want = referenceFanPixel(s, t, colorOffset, flat, span.x + k, span.y);
      expectSamePixel(want, span, k, "trial " + std::to_string(trial) + " pixel " + std::to_string(k));
    }
  }
  EXPECT_GT(fanTriangles, 3000);  // clipped triangles made fans
  EXPECT_GT(uniformSpans, 200);   // the shortcut was exercised
  EXPECT_GT(perPixelSpans, 1000);
}

}  // namespace
}  // namespace mpr
