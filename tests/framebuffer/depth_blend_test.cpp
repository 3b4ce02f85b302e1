// Depth test, blending, alpha test and colour mask through processFragment.
#include <gtest/gtest.h>

#include "framebuffer/fragment_ops.hpp"

namespace mpr {
namespace {

TEST(DepthTest, EveryFunctionAtLessEqualGreater) {
  // incoming 100 against stored 99 (incoming greater), 100 (equal), 101 (less).
  struct Case { CompareFunc f; bool greater, equal, less; };
  const Case cases[] = {
      {CompareFunc::Never, false, false, false},  {CompareFunc::Less, false, false, true},
      {CompareFunc::Equal, false, true, false},   {CompareFunc::Lequal, false, true, true},
      {CompareFunc::Greater, true, false, false}, {CompareFunc::Notequal, true, false, true},
      {CompareFunc::Gequal, true, true, false},   {CompareFunc::Always, true, true, true},
  };
  for (const Case& c : cases) {
    const std::uint32_t stored[3] = {99, 100, 101};
    const bool expect[3] = {c.greater, c.equal, c.less};
    for (int i = 0; i < 3; ++i) {
      Framebuffer fb(1, 1, indigoProfile());
      FragmentState s;
      s.depth.enabled = true;
      s.depth.func = c.f;
      fb.depth(0, 0) = stored[i];
      const FragmentFate fate = processFragment(s, fb, Fragment{0, 0, 100, Rgba8{9, 9, 9, 9}, 1.0f});
      EXPECT_EQ(fate == FragmentFate::Written, expect[i]) << int(c.f) << " vs " << stored[i];
      EXPECT_EQ(fb.depth(0, 0), expect[i] ? 100u : stored[i]);
    }
  }
}

TEST(DepthTest, MaskAndDisabledTestWriteNothing) {
  Framebuffer fb(1, 1, indigoProfile());
  FragmentState s;
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Always;
  s.depth.writeMask = false;
  fb.depth(0, 0) = 0xFFFFFF;
  processFragment(s, fb, Fragment{0, 0, 0, Rgba8{1, 1, 1, 1}, 1.0f});
  EXPECT_EQ(fb.depth(0, 0), 0xFFFFFFu);
  EXPECT_EQ(fb.color(0, 0), (Rgba8{1, 1, 1, 1}));
  s.depth.enabled = false;
  s.depth.writeMask = true;
  processFragment(s, fb, Fragment{0, 0, 0, Rgba8{2, 2, 2, 2}, 1.0f});
  EXPECT_EQ(fb.depth(0, 0), 0xFFFFFFu);  // GL: no test, no update
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Less;
  processFragment(s, fb, Fragment{0, 0, 0xFFFFFE, Rgba8{3, 3, 3, 3}, 1.0f});
  EXPECT_EQ(fb.depth(0, 0), 0xFFFFFEu);
  processFragment(s, fb, Fragment{0, 0, 0, Rgba8{3, 3, 3, 3}, 1.0f});
  EXPECT_EQ(fb.depth(0, 0), 0u);
}

TEST(Blend, EveryFactorByHand) {
  const Rgba8 s{200, 100, 50, 128}, d{40, 80, 160, 64};
  // Source factor alone (destination ZERO): result = round(s * f / 255).
  struct Case { BlendFactor f; Rgba8 expected; };
  const Case asSource[] = {
      {BlendFactor::Zero, {0, 0, 0, 0}},
      {BlendFactor::One, {200, 100, 50, 128}},
      {BlendFactor::SrcColor, {157, 39, 10, 64}},           // 200*200/255 = 156.9; 100*100/255 = 39.2; 50*50/255 = 9.8; 128*128/255 = 64.25
      {BlendFactor::OneMinusSrcColor, {43, 61, 40, 64}},    // 200*55/255 = 43.1; 100*155/255 = 60.8; 50*205/255 = 40.2; 128*127/255 = 63.75
      {BlendFactor::DstColor, {31, 31, 31, 32}},            // 200*40/255 = 31.4; 100*80/255 = 31.4; 50*160/255 = 31.4; 128*64/255 = 32.1
      {BlendFactor::OneMinusDstColor, {169, 69, 19, 96}},   // 200*215/255 = 168.6; 100*175/255 = 68.6; 50*95/255 = 18.6; 128*191/255 = 95.9
      {BlendFactor::SrcAlpha, {100, 50, 25, 64}},           // x*128/255: 100.4, 50.2, 25.1, 64.25
      {BlendFactor::OneMinusSrcAlpha, {100, 50, 25, 64}},   // x*127/255: 99.6, 49.8, 24.9, 63.75
      {BlendFactor::DstAlpha, {50, 25, 13, 32}},            // x*64/255: 50.2, 25.1, 12.5490, 32.1
      {BlendFactor::OneMinusDstAlpha, {150, 75, 37, 96}},   // x*191/255: 149.8, 74.9, 37.45, 95.9
      {BlendFactor::SrcAlphaSaturate, {100, 50, 25, 128}},  // f = min(128, 255-64) = 128 for RGB, 1 for alpha
  };
  for (const Case& c : asSource) {
    BlendState b{true, c.f, BlendFactor::Zero};
    EXPECT_EQ(blend(b, s, d), c.expected) << "source factor " << int(c.f);
  }
  // Destination factors (source ZERO).
  const Case asDest[] = {
      {BlendFactor::One, {40, 80, 160, 64}},
      {BlendFactor::SrcColor, {31, 31, 31, 32}},           // 40*200/255 = 31.4; 80*100/255 = 31.4; 160*50/255 = 31.4; 64*128/255 = 32.1
      {BlendFactor::OneMinusSrcColor, {9, 49, 129, 32}},   // 40*55/255 = 8.6; 80*155/255 = 48.6; 160*205/255 = 128.6; 64*127/255 = 31.9
      {BlendFactor::SrcAlpha, {20, 40, 80, 32}},           // x*128/255: 20.08, 40.2, 80.3, 32.1
      {BlendFactor::OneMinusDstAlpha, {30, 60, 120, 48}},  // x*191/255: 29.96, 59.9, 119.8, 47.9
  };
  for (const Case& c : asDest) {
    BlendState b{true, BlendFactor::Zero, c.f};
    EXPECT_EQ(blend(b, s, d), c.expected) << "destination factor " << int(c.f);
  }
  // The classic over operator saturates nothing: 100+20 etc. And ONE+ONE saturates.
  EXPECT_EQ(blend(BlendState{true, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha}, s, d),
            (Rgba8{120, 90, 105, 96}));  // (100+20, 50+40, 25+80, 64+32)
  EXPECT_EQ(blend(BlendState{true, BlendFactor::One, BlendFactor::One}, s, d), (Rgba8{240, 180, 210, 192}));
  EXPECT_EQ(blend(BlendState{true, BlendFactor::One, BlendFactor::One}, Rgba8{200, 255, 0, 255}, Rgba8{100, 1, 0, 1}),
            (Rgba8{255, 255, 0, 255}));
}

TEST(Blend, ColourMaskPerChannelAndAlphaTest) {
  Framebuffer fb(1, 1, indigoProfile());
  fb.color(0, 0) = Rgba8{10, 20, 30, 40};
  FragmentState s;
  s.colorMask = {true, false, true, false};
  processFragment(s, fb, Fragment{0, 0, 0, Rgba8{1, 2, 3, 4}, 1.0f});
  EXPECT_EQ(fb.color(0, 0), (Rgba8{1, 20, 3, 40}));
  s.colorMask = {true, true, true, true};
  s.alpha.enabled = true;
  s.alpha.func = CompareFunc::Gequal;
  s.alpha.ref = 0.5f;
  fb.stencil(0, 0) = 7;
  s.stencil.enabled = true;
  s.stencil.sfail = s.stencil.dpfail = s.stencil.dppass = StencilOp::Zero;
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0, Rgba8{9, 9, 9, 9}, 0.25f}), FragmentFate::AlphaFailed);
  EXPECT_EQ(fb.stencil(0, 0), 7u);  // the alpha test comes before the stencil test
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0, Rgba8{9, 9, 9, 9}, 0.5f}), FragmentFate::Written);
  EXPECT_EQ(fb.stencil(0, 0), 0u);
}

TEST(FloatToUnorm8, ClampsAndRoundsToNearestEven) {
  EXPECT_EQ(floatToUnorm8(-1.0f), 0);
  EXPECT_EQ(floatToUnorm8(2.0f), 255);
  EXPECT_EQ(floatToUnorm8(0.5f), 128);  // 127.5 -> even 128
  EXPECT_EQ(floatToUnorm8(1.5f / 255.0f), 2);  // 1.5 -> 2
  EXPECT_EQ(floatToUnorm8(0.1f), 26);  // 25.5 in float is 25.500000372...
}

}  // namespace
}  // namespace mpr
