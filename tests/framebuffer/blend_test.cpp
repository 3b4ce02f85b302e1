// Blending on 8-bit colour (GL 1.1 section 4.1.6), the colour write mask and
// the alpha test, per pixel and exactly. The documented blender:
//     out = min(255, round(s * sf / 255) + round(d * df / 255))
// per channel, each product rounded to nearest on its own; the factor of
// SRC_ALPHA_SATURATE is min(As, 255 - Ad) for R, G, B and 255 for A.
// Every expected byte is derived by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "framebuffer/blend.hpp"
#include "framebuffer/compare_func.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "support/compare_funcs.hpp"

namespace mpr {
namespace {

// ---------------------------------------------------------------------------
// mulUnorm8: llvmpipe's unorm8 product, round(a * b / 255) but for 24 pairs
// ---------------------------------------------------------------------------

// The pairs (a <= b) where llvmpipe's (t + (t >> 8) + 128) >> 8 is one below
// round(ab/255): all have ab/255 = k + 128/255 = k + 0.50196, the closest a
// product comes to a half from above. Measured on Mesa 22.3.6 llvmpipe
// (169 * 212 blended to 140, not 141).
struct LowPair { std::uint32_t a, b, value; };
constexpr LowPair kLowPairs[] = {
    {152, 229, 136}, {169, 212, 140}, {173, 241, 163}, {188, 196, 144},
    {191, 253, 189}, {194, 232, 176}, {197, 244, 188}, {208, 236, 192},
    {214, 227, 190}, {223, 251, 219}, {226, 233, 206}, {239, 247, 231}};

bool isLowPair(std::uint32_t a, std::uint32_t b) {
  for (const LowPair& p : kLowPairs)
    if ((p.a == a && p.b == b) || (p.a == b && p.b == a)) return true;
  return false;
}

// round(ab/255) = floor(ab/255 + 1/2) = floor((2ab + 255) / 510). There is
// never a tie: ab/255 = k + 1/2 would need 2ab = 255 (2k + 1), even = odd.
TEST(MulUnorm8, EqualsIntegerRoundingExceptTheLowPairs) {
  int wrong = 0;
  for (std::uint32_t a = 0; a < 256; ++a)
    for (std::uint32_t b = 0; b < 256; ++b) {
      const std::uint32_t rounded = (2 * a * b + 255) / 510;
      const std::uint32_t want = isLowPair(a, b) ? rounded - 1 : rounded;
      if (mulUnorm8(a, b) != want && ++wrong <= 10)
        ADD_FAILURE() << a << " * " << b << ": expected " << want << ", got " << mulUnorm8(a, b);
    }
  EXPECT_EQ(wrong, 0);
}

TEST(MulUnorm8, LowPairsSitJustAboveAHalf) {
  for (const LowPair& p : kLowPairs) {
    EXPECT_EQ(mulUnorm8(p.a, p.b), p.value);
    EXPECT_EQ(mulUnorm8(p.b, p.a), p.value);
    EXPECT_EQ((p.a * p.b) % 255, 128u) << p.a << " * " << p.b;  // ab/255 = value + 128/255
    EXPECT_EQ((p.a * p.b) / 255, p.value);
  }
}

TEST(MulUnorm8, HandPickedNearHalves) {
  EXPECT_EQ(mulUnorm8(0, 200), 0u);
  EXPECT_EQ(mulUnorm8(255, 200), 200u);   // 1.0 * x = x
  EXPECT_EQ(mulUnorm8(255, 255), 255u);
  EXPECT_EQ(mulUnorm8(1, 127), 0u);       // 127/255 = 0.498
  EXPECT_EQ(mulUnorm8(1, 128), 1u);       // 128/255 = 0.502
  EXPECT_EQ(mulUnorm8(3, 42), 0u);        // 126/255 = 0.494
  EXPECT_EQ(mulUnorm8(3, 43), 1u);        // 129/255 = 0.506
  EXPECT_EQ(mulUnorm8(127, 127), 63u);    // 16129/255 = 63.25
  EXPECT_EQ(mulUnorm8(128, 128), 64u);    // 16384/255 = 64.25
  EXPECT_EQ(mulUnorm8(254, 254), 253u);   // 64516/255 = 253.004
  EXPECT_EQ(mulUnorm8(200, 153), 120u);   // 30600/255 = 120 exactly
}

// ---------------------------------------------------------------------------
// Every factor, through processFragment
// ---------------------------------------------------------------------------

constexpr std::array<BlendFactor, 11> kFactors = {
    BlendFactor::Zero,     BlendFactor::One,           BlendFactor::SrcColor,
    BlendFactor::OneMinusSrcColor, BlendFactor::DstColor, BlendFactor::OneMinusDstColor,
    BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendFactor::DstAlpha,
    BlendFactor::OneMinusDstAlpha, BlendFactor::SrcAlphaSaturate};
constexpr std::array<const char*, 11> kFactorNames = {
    "ZERO",      "ONE",       "SRC_COLOR",           "ONE_MINUS_SRC_COLOR",
    "DST_COLOR", "ONE_MINUS_DST_COLOR", "SRC_ALPHA", "ONE_MINUS_SRC_ALPHA",
    "DST_ALPHA", "ONE_MINUS_DST_ALPHA", "SRC_ALPHA_SATURATE"};

// Source (200, 100, 50, 153) and destination (40, 90, 160, 51);
// 153 = 0.6, 102 = 0.4, 51 = 0.2 and 204 = 0.8 of 255.
constexpr Rgba8 kS{200, 100, 50, 153};
constexpr Rgba8 kD{40, 90, 160, 51};

FragmentState blendState(BlendFactor src, BlendFactor dst) {
  FragmentState s;
  s.blend.enabled = true;
  s.blend.src = src;
  s.blend.dst = dst;
  return s;
}

// One pixel holding `dst`, one fragment `src` blended onto it.
Rgba8 blendPixel(BlendFactor sf, BlendFactor df, Rgba8 src, Rgba8 dst) {
  Framebuffer fb(1, 1, indigoProfile());
  fb.color(0, 0) = dst;
  EXPECT_EQ(processFragment(blendState(sf, df), fb, Fragment{0, 0, 0, src, src[3] / 255.0f}),
            FragmentFate::Written);
  return fb.color(0, 0);
}

// Each factor as the source factor with destination factor ZERO:
// out = round(s * sf / 255).
TEST(BlendFactorSource, EveryFactorByHand) {
  const std::array<Rgba8, 11> expected = {{
      {0, 0, 0, 0},          // ZERO
      {200, 100, 50, 153},   // ONE
      // SRC_COLOR: 200*200/255 = 156.86, 100*100/255 = 39.22, 50*50/255 = 9.80, 153*153/255 = 91.8
      {157, 39, 10, 92},
      // ONE_MINUS_SRC_COLOR (55, 155, 205, 102): 43.14, 60.78, 40.20, 61.2
      {43, 61, 40, 61},
      // DST_COLOR (40, 90, 160, 51): 8000/255 = 31.37, 9000/255 = 35.29, 8000/255, 7803/255 = 30.6
      {31, 35, 31, 31},
      // ONE_MINUS_DST_COLOR (215, 165, 95, 204): 168.63, 64.71, 18.63, 122.4
      {169, 65, 19, 122},
      // SRC_ALPHA (0.6): 120, 60, 30, 91.8
      {120, 60, 30, 92},
      // ONE_MINUS_SRC_ALPHA (0.4): 80, 40, 20, 61.2
      {80, 40, 20, 61},
      // DST_ALPHA (0.2): 40, 20, 10, 30.6
      {40, 20, 10, 31},
      // ONE_MINUS_DST_ALPHA (0.8): 160, 80, 40, 122.4
      {160, 80, 40, 122},
      // SRC_ALPHA_SATURATE: f = min(153, 255 - 51 = 204) = 153 for RGB
      // (= SRC_ALPHA: 120, 60, 30), and 255 for alpha: 153.
      {120, 60, 30, 153},
  }};
  for (int k = 0; k < 11; ++k)
    EXPECT_EQ(blendPixel(kFactors[k], BlendFactor::Zero, kS, kD), expected[k]) << kFactorNames[k];
}

TEST(BlendFactorSource, AlphaSaturateTakesOneMinusDstAlphaWhenSmaller) {
  // Destination alpha 204: 1 - Ad = 51 < As = 153, so f = 51 (0.2) for RGB:
  // 200 * 0.2 = 40, 100 * 0.2 = 20, 50 * 0.2 = 10; alpha factor 255: 153.
  EXPECT_EQ(blendPixel(BlendFactor::SrcAlphaSaturate, BlendFactor::Zero, kS, Rgba8{40, 90, 160, 204}),
            (Rgba8{40, 20, 10, 153}));
  // Destination alpha 255: f = 0 for RGB; alpha still 153 * 255/255.
  EXPECT_EQ(blendPixel(BlendFactor::SrcAlphaSaturate, BlendFactor::Zero, kS, Rgba8{40, 90, 160, 255}),
            (Rgba8{0, 0, 0, 153}));
  // Destination alpha 0: f = min(153, 255) = 153.
  EXPECT_EQ(blendPixel(BlendFactor::SrcAlphaSaturate, BlendFactor::Zero, kS, Rgba8{40, 90, 160, 0}),
            (Rgba8{120, 60, 30, 153}));
}

// Each factor as the destination factor with source factor ZERO:
// out = round(d * df / 255). (GL 1.1 accepts SRC_ALPHA_SATURATE only as the
// source factor; the GL layer rejects it as dfactor, so it is not tested here.)
TEST(BlendFactorDestination, EveryFactorByHand) {
  const std::array<Rgba8, 10> expected = {{
      {0, 0, 0, 0},        // ZERO
      {40, 90, 160, 51},   // ONE
      // SRC_COLOR (200, 100, 50, 153): 8000/255 = 31.37, 9000/255 = 35.29, 8000/255, 7803/255 = 30.6
      {31, 35, 31, 31},
      // ONE_MINUS_SRC_COLOR (55, 155, 205, 102): 2200/255 = 8.63, 13950/255 = 54.71,
      // 32800/255 = 128.63, 5202/255 = 20.4
      {9, 55, 129, 20},
      // DST_COLOR: 1600/255 = 6.27, 8100/255 = 31.76, 25600/255 = 100.39, 2601/255 = 10.2
      {6, 32, 100, 10},
      // ONE_MINUS_DST_COLOR (215, 165, 95, 204): 8600/255 = 33.73, 14850/255 = 58.24,
      // 15200/255 = 59.61, 10404/255 = 40.8
      {34, 58, 60, 41},
      // SRC_ALPHA (0.6): 24, 54, 96, 30.6
      {24, 54, 96, 31},
      // ONE_MINUS_SRC_ALPHA (0.4): 16, 36, 64, 20.4
      {16, 36, 64, 20},
      // DST_ALPHA (0.2): 8, 18, 32, 10.2
      {8, 18, 32, 10},
      // ONE_MINUS_DST_ALPHA (0.8): 32, 72, 128, 40.8
      {32, 72, 128, 41},
  }};
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(blendPixel(BlendFactor::Zero, kFactors[k], kS, kD), expected[k]) << kFactorNames[k];
}

TEST(BlendCombined, ClassicTransparency) {
  // SRC_ALPHA, ONE_MINUS_SRC_ALPHA: the two tables above added channel by
  // channel: (120 + 16, 60 + 36, 30 + 64, 92 + 20).
  EXPECT_EQ(blendPixel(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, kS, kD), (Rgba8{136, 96, 94, 112}));
}

TEST(BlendCombined, SumSaturatesAt255) {
  // ONE, ONE: 200 + 100 = 300, 255 + 1 = 256, 0 + 255 = 255, 128 + 128 = 256 -> all 255.
  EXPECT_EQ(blendPixel(BlendFactor::One, BlendFactor::One, Rgba8{200, 255, 0, 128}, Rgba8{100, 1, 255, 128}),
            (Rgba8{255, 255, 255, 255}));
  // Just below: 200 + 55 = 255, 254 + 0 = 254.
  EXPECT_EQ(blendPixel(BlendFactor::One, BlendFactor::One, Rgba8{200, 254, 0, 1}, Rgba8{55, 0, 0, 2}),
            (Rgba8{255, 254, 0, 3}));
}

TEST(BlendCombined, EachProductRoundsOnItsOwn) {
  // s = d = (1, 1, 1, 128). SRC_ALPHA (128) and DST_ALPHA (128):
  //   RGB: round(128/255 = 0.502) + round(0.502) = 1 + 1 = 2 (the exact sum
  //   256/255 would round to 1); A: round(16384/255 = 64.25) * 2 = 128.
  EXPECT_EQ(blendPixel(BlendFactor::SrcAlpha, BlendFactor::DstAlpha, Rgba8{1, 1, 1, 128}, Rgba8{1, 1, 1, 128}),
            (Rgba8{2, 2, 2, 128}));
  // ONE_MINUS_SRC_ALPHA (127) and ONE_MINUS_DST_ALPHA (127):
  //   RGB: round(127/255 = 0.498) * 2 = 0 (the exact 254/255 would be 1);
  //   A: round(128 * 127 / 255 = 63.75) * 2 = 128.
  EXPECT_EQ(blendPixel(BlendFactor::OneMinusSrcAlpha, BlendFactor::OneMinusDstAlpha, Rgba8{1, 1, 1, 128},
                       Rgba8{1, 1, 1, 128}),
            (Rgba8{0, 0, 0, 128}));
}

TEST(BlendCombined, DisabledBlendingReplaces) {
  // Blending off: the fragment colour is written whatever the factors say.
  Framebuffer fb(1, 1, indigoProfile());
  fb.color(0, 0) = kD;
  FragmentState s = blendState(BlendFactor::Zero, BlendFactor::One);
  s.blend.enabled = false;
  processFragment(s, fb, Fragment{0, 0, 0, kS, 0.6f});
  EXPECT_EQ(fb.color(0, 0), kS);
}

// ---------------------------------------------------------------------------
// Colour write mask
// ---------------------------------------------------------------------------

TEST(BlendColourMask, EveryMaskWithAndWithoutBlending) {
  // Blended value (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) is (136, 96, 94, 112), see
  // ClassicTransparency; unblended it is the source (200, 100, 50, 153).
  // Channel c of the result is the new value where mask bit c is on, and the
  // old destination (40, 90, 160, 51) where it is off. Pixel x = mask number
  // (bit 0 = R, bit 1 = G, bit 2 = B, bit 3 = A).
  const Rgba8 blended{136, 96, 94, 112};
  for (bool blending : {false, true}) {
    SCOPED_TRACE(blending ? "blending" : "no blending");
    Framebuffer fb(16, 1, indigoProfile());
    for (int x = 0; x < 16; ++x) fb.color(x, 0) = kD;
    FragmentState s = blendState(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha);
    s.blend.enabled = blending;
    for (int x = 0; x < 16; ++x) {
      s.colorMask = {(x & 1) != 0, (x & 2) != 0, (x & 4) != 0, (x & 8) != 0};
      EXPECT_EQ(processFragment(s, fb, Fragment{x, 0, 0, kS, 0.6f}), FragmentFate::Written);
    }
    const Rgba8 v = blending ? blended : kS;
    for (int x = 0; x < 16; ++x) {
      const Rgba8 want{(x & 1) ? v[0] : kD[0], (x & 2) ? v[1] : kD[1], (x & 4) ? v[2] : kD[2],
                       (x & 8) ? v[3] : kD[3]};
      EXPECT_EQ(fb.color(x, 0), want) << "mask " << x;
    }
  }
  // Spelled out for two masks: R only -> (200, 90, 160, 51); G, A -> (40, 100, 160, 153).
  Framebuffer fb(2, 1, indigoProfile());
  fb.color(0, 0) = fb.color(1, 0) = kD;
  FragmentState s;
  s.colorMask = {true, false, false, false};
  processFragment(s, fb, Fragment{0, 0, 0, kS, 0.6f});
  s.colorMask = {false, true, false, true};
  processFragment(s, fb, Fragment{1, 0, 0, kS, 0.6f});
  EXPECT_EQ(fb.color(0, 0), (Rgba8{200, 90, 160, 51}));
  EXPECT_EQ(fb.color(1, 0), (Rgba8{40, 100, 160, 153}));
}

// ---------------------------------------------------------------------------
// Alpha test (GL 1.1 section 4.1.3): incoming alpha FUNC ref, both
// converted to the colour buffer's fixed point first
// ---------------------------------------------------------------------------

using test::kFuncNames;
using test::kFuncs;

FragmentState alphaState(CompareFunc f, float ref) {
  FragmentState s;
  s.alpha.enabled = true;
  s.alpha.func = f;
  s.alpha.ref = ref;
  return s;
}

bool alphaPasses(CompareFunc f, float ref, float alpha) {
  Framebuffer fb(1, 1, indigoProfile());
  const FragmentFate fate = processFragment(alphaState(f, ref), fb, Fragment{0, 0, 0, Rgba8{1, 2, 3, 4}, alpha});
  EXPECT_TRUE(fate == FragmentFate::Written || fate == FragmentFate::AlphaFailed);
  // A failing fragment writes nothing.
  EXPECT_EQ(fb.color(0, 0), fate == FragmentFate::Written ? (Rgba8{1, 2, 3, 4}) : (Rgba8{0, 0, 0, 0}));
  return fate == FragmentFate::Written;
}

TEST(AlphaFunc, EveryFunctionAroundHalf) {
  // ref 0.5; alpha 0.25 (less), 0.5 (equal), 0.75 (greater).
  const std::array<std::array<bool, 3>, 8> table = {{
      {false, false, false},  // NEVER
      {true, false, false},   // LESS:     alpha <  0.5
      {false, true, false},   // EQUAL
      {true, true, false},    // LEQUAL
      {false, false, true},   // GREATER:  alpha >  0.5
      {true, false, true},    // NOTEQUAL
      {false, true, true},    // GEQUAL
      {true, true, true},     // ALWAYS
  }};
  const std::array<float, 3> alphas = {0.25f, 0.5f, 0.75f};
  for (int f = 0; f < 8; ++f)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(alphaPasses(kFuncs[f], 0.5f, alphas[i]), table[f][i]) << kFuncNames[f] << " alpha " << alphas[i];
}

TEST(AlphaFunc, ComparesInColourBufferPrecision) {
  // GL 1.1 section 4.1.3: ref and the fragment's alpha are both converted to
  // the colour buffer's fixed point (bytes here, round to nearest even)
  // before the comparison. 0.5 is 127.5, the byte 128 (to even); one ulp
  // above is 128 too (equal, not greater), one ulp below is 127.49999: 127.
  const float below = std::nextafter(0.5f, 0.0f), above = std::nextafter(0.5f, 1.0f);
  EXPECT_TRUE(alphaPasses(CompareFunc::Less, 0.5f, below));
  EXPECT_FALSE(alphaPasses(CompareFunc::Less, 0.5f, 0.5f));
  EXPECT_TRUE(alphaPasses(CompareFunc::Equal, 0.5f, above));
  EXPECT_FALSE(alphaPasses(CompareFunc::Greater, 0.5f, above));
  EXPECT_TRUE(alphaPasses(CompareFunc::Less, 0.5f, 0.498f));  // 126.99: byte 127
  // ref 0: GREATER fails at 0.001 (byte 0) and passes at 0.002 (0.51: byte 1).
  EXPECT_FALSE(alphaPasses(CompareFunc::Greater, 0.0f, 0.0f));
  EXPECT_FALSE(alphaPasses(CompareFunc::Greater, 0.0f, 0.001f));
  EXPECT_TRUE(alphaPasses(CompareFunc::Greater, 0.0f, 0.002f));
  // ref 1: LESS fails at 0.999 (254.7: byte 255) and passes at 0.997 (254).
  EXPECT_FALSE(alphaPasses(CompareFunc::Less, 1.0f, 1.0f));
  EXPECT_FALSE(alphaPasses(CompareFunc::Less, 1.0f, 0.999f));
  EXPECT_TRUE(alphaPasses(CompareFunc::Less, 1.0f, 0.997f));
  EXPECT_TRUE(alphaPasses(CompareFunc::Equal, 1.0f, 1.0f));
  // A ref between two bytes: 0.3 (76.5: byte 76, the even one) against
  // alpha 0.3 and 0.29 (73.95: byte 74).
  EXPECT_TRUE(alphaPasses(CompareFunc::Gequal, 0.3f, 0.3f));
  EXPECT_FALSE(alphaPasses(CompareFunc::Gequal, 0.3f, 0.29f));
  // perspective seed 11 (alpha_test_fixed_point.gls): alpha 0.58265 is below
  // ref 0.58364 as floats, but both are the byte 149, so GEQUAL passes.
  EXPECT_TRUE(alphaPasses(CompareFunc::Gequal, 0.58364f, 0.58265f));
  EXPECT_FALSE(alphaPasses(CompareFunc::Less, 0.58364f, 0.58265f));
}

TEST(AlphaFunc, TestsTheFloatAlphaNotTheColourByte) {
  // The colour's alpha byte is 255 but the fragment's alpha is 0.25:
  // LESS 0.5 passes, and the byte 255 is what gets written.
  Framebuffer fb(1, 1, indigoProfile());
  EXPECT_EQ(processFragment(alphaState(CompareFunc::Less, 0.5f), fb, Fragment{0, 0, 0, Rgba8{9, 9, 9, 255}, 0.25f}),
            FragmentFate::Written);
  EXPECT_EQ(fb.color(0, 0), (Rgba8{9, 9, 9, 255}));
}

TEST(AlphaFunc, DisabledTestPassesEverything) {
  Framebuffer fb(1, 1, indigoProfile());
  FragmentState s = alphaState(CompareFunc::Never, 0.5f);
  s.alpha.enabled = false;
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0, Rgba8{5, 6, 7, 8}, 0.0f}), FragmentFate::Written);
  EXPECT_EQ(fb.color(0, 0), (Rgba8{5, 6, 7, 8}));
}

}  // namespace
}  // namespace mpr
