// The order of the per-fragment operations (GL 1.1 chapter 4.1): alpha test,
// stencil test, depth test (with the stencil update chosen by their
// outcomes), blending, colour mask. A fragment rejected by one stage touches
// nothing any later stage would write. Also the framebuffer's refusal of
// sizes it will not allocate. Expected values are written by hand.
#include <gtest/gtest.h>

#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "framebuffer/compare_func.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "support/stencil_picture.hpp"

namespace mpr {
namespace {

using test::stencilMatches;

constexpr Rgba8 kOld{1, 2, 3, 4};
constexpr Rgba8 kNew{100, 110, 120, 130};

// One pixel with stencil 77, depth 0x400 and colour kOld.
Framebuffer onePixel() {
  Framebuffer fb(1, 1, indigoProfile());
  fb.stencil(0, 0) = 77;
  fb.depth(0, 0) = 0x400;
  fb.color(0, 0) = kOld;
  return fb;
}

// Every later stage enabled and eager to write: stencil ops that change the
// value whichever is chosen, depth ALWAYS with writes on, blending ONE, ONE.
FragmentState eager() {
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.func = CompareFunc::Always;
  s.stencil.ref = 200;
  s.stencil.sfail = StencilOp::Replace;  // -> 200
  s.stencil.dpfail = StencilOp::Incr;    // -> 78
  s.stencil.dppass = StencilOp::Zero;    // -> 0
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Always;
  s.blend.enabled = true;
  s.blend.src = BlendFactor::One;
  s.blend.dst = BlendFactor::One;
  return s;
}

TEST(FragmentOrder, AlphaFailureTouchesNothing) {
  // Alpha GREATER 0.5 with alpha 0.25 fails before the stencil test: no
  // stencil op runs, whichever of sfail / dpfail / dppass the fragment would
  // have reached.
  for (CompareFunc stencilFunc : {CompareFunc::Never, CompareFunc::Always}) {
    for (CompareFunc depthFunc : {CompareFunc::Never, CompareFunc::Always}) {
      Framebuffer fb = onePixel();
      FragmentState s = eager();
      s.alpha.enabled = true;
      s.alpha.func = CompareFunc::Greater;
      s.alpha.ref = 0.5f;
      s.stencil.func = stencilFunc;
      s.depth.func = depthFunc;
      EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0x100, kNew, 0.25f}), FragmentFate::AlphaFailed);
      EXPECT_EQ(fb.stencil(0, 0), 77);
      EXPECT_EQ(fb.depth(0, 0), 0x400u);
      EXPECT_EQ(fb.color(0, 0), kOld);
    }
  }
}

TEST(FragmentOrder, StencilFailureLeavesDepthAndColour) {
  // The stencil test fails: sfail (REPLACE 200) runs, and neither the depth
  // (which ALWAYS would have passed and written 0x100) nor the colour changes.
  Framebuffer fb = onePixel();
  FragmentState s = eager();
  s.stencil.func = CompareFunc::Never;
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0x100, kNew, 1.0f}), FragmentFate::StencilFailed);
  EXPECT_EQ(fb.stencil(0, 0), 200);
  EXPECT_EQ(fb.depth(0, 0), 0x400u);
  EXPECT_EQ(fb.color(0, 0), kOld);
}

TEST(FragmentOrder, StencilIsTestedBeforeDepth) {
  // Both tests would fail: the stencil test comes first, so sfail (200)
  // applies, not dpfail (78).
  Framebuffer fb = onePixel();
  FragmentState s = eager();
  s.stencil.func = CompareFunc::Never;
  s.depth.func = CompareFunc::Never;
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0x100, kNew, 1.0f}), FragmentFate::StencilFailed);
  EXPECT_EQ(fb.stencil(0, 0), 200);
}

TEST(FragmentOrder, DepthFailureAppliesDpfailOnly) {
  // Stencil passes, depth LESS fails (0x500 is not < 0x400): dpfail (INCR)
  // gives 78; depth and colour stay.
  Framebuffer fb = onePixel();
  FragmentState s = eager();
  s.depth.func = CompareFunc::Less;
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0x500, kNew, 1.0f}), FragmentFate::DepthFailed);
  EXPECT_EQ(fb.stencil(0, 0), 78);
  EXPECT_EQ(fb.depth(0, 0), 0x400u);
  EXPECT_EQ(fb.color(0, 0), kOld);
}

TEST(FragmentOrder, PassingFragmentDoesEverythingOnce) {
  // Both pass: dppass (ZERO) -> 0, depth 0x100 stored, colour blended ONE,
  // ONE onto the old value: (1+100, 2+110, 3+120, 4+130), then masked: with
  // alpha masked off the alpha stays 4.
  Framebuffer fb = onePixel();
  FragmentState s = eager();
  s.depth.func = CompareFunc::Less;
  s.colorMask = {true, true, true, false};
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 0x100, kNew, 1.0f}), FragmentFate::Written);
  EXPECT_EQ(fb.stencil(0, 0), 0);
  EXPECT_EQ(fb.depth(0, 0), 0x100u);
  EXPECT_EQ(fb.color(0, 0), (Rgba8{101, 112, 123, 4}));
  // INCR as dppass from 5 gives 6: the op runs once per fragment.
  fb.stencil(0, 0) = 5;
  s.stencil.dppass = StencilOp::Incr;
  processFragment(s, fb, Fragment{0, 0, 0x50, kNew, 1.0f});
  EXPECT_EQ(fb.stencil(0, 0), 6);
}

TEST(FragmentOrder, FourFatesSideBySide) {
  // Four pixels, stencil 10, depth 100, colour kOld; sfail INVERT, dpfail
  // INCR, dppass DECR; alpha GEQUAL 0.5; stencil EQUAL 10; depth LESS.
  //   x = 0: alpha 0.1 fails             -> stencil 10 (untouched)
  //   x = 1: stored stencil 20 != 10     -> sfail INVERT: 255 - 20 = 235
  //   x = 2: depth 200 not < 100         -> dpfail INCR: 11
  //   x = 3: all pass (depth 50)         -> dppass DECR: 9, depth 50, colour kNew
  Framebuffer fb(4, 1, indigoProfile());
  for (int x = 0; x < 4; ++x) {
    fb.stencil(x, 0) = 10;
    fb.depth(x, 0) = 100;
    fb.color(x, 0) = kOld;
  }
  fb.stencil(1, 0) = 20;
  FragmentState s;
  s.alpha = {true, CompareFunc::Gequal, 0.5f};
  s.stencil.enabled = true;
  s.stencil.func = CompareFunc::Equal;
  s.stencil.ref = 10;
  s.stencil.sfail = StencilOp::Invert;
  s.stencil.dpfail = StencilOp::Incr;
  s.stencil.dppass = StencilOp::Decr;
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Less;
  EXPECT_EQ(processFragment(s, fb, Fragment{0, 0, 50, kNew, 0.1f}), FragmentFate::AlphaFailed);
  EXPECT_EQ(processFragment(s, fb, Fragment{1, 0, 50, kNew, 1.0f}), FragmentFate::StencilFailed);
  EXPECT_EQ(processFragment(s, fb, Fragment{2, 0, 200, kNew, 1.0f}), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(s, fb, Fragment{3, 0, 50, kNew, 1.0f}), FragmentFate::Written);
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "10 235 11 9"));
  for (int x = 0; x < 3; ++x) {
    EXPECT_EQ(fb.depth(x, 0), 100u) << x;
    EXPECT_EQ(fb.color(x, 0), kOld) << x;
  }
  EXPECT_EQ(fb.depth(3, 0), 50u);
  EXPECT_EQ(fb.color(3, 0), kNew);
}

TEST(FragmentOrder, FragmentsTouchOnlyTheirOwnPixel) {
  // A fragment at (2, 1) in a 4x3 window changes that pixel's stencil only.
  Framebuffer fb(4, 3, indigoProfile());
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.dppass = StencilOp::Invert;
  processFragment(s, fb, Fragment{2, 1, 0, kNew, 1.0f});
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    .  .   .  .
    .  .  255 .
    .  .   .  .
  )"));
  // Rows are stored bottom-up: (2, 1) is element 1 * 4 + 2 = 6.
  EXPECT_EQ(fb.stencilData()[6], 255);
  EXPECT_EQ(fb.colorData()[6], kNew);
}

// ---------------------------------------------------------------------------
// Framebuffer sizes
// ---------------------------------------------------------------------------

TEST(FramebufferSize, CheckSizeAcceptsOneToMaxSide) {
  EXPECT_EQ(Framebuffer::kMaxSide, 16384);
  EXPECT_EQ(Framebuffer::checkSize(1, 1), "");
  EXPECT_EQ(Framebuffer::checkSize(640, 480), "");
  EXPECT_EQ(Framebuffer::checkSize(16384, 1), "");
  EXPECT_EQ(Framebuffer::checkSize(1, 16384), "");
  EXPECT_EQ(Framebuffer::checkSize(16384, 16384), "");
}

TEST(FramebufferSize, CheckSizeRefusesNonPositiveAndTooLarge) {
  const int refused[][2] = {{0, 1},       {1, 0},      {0, 0},          {-1, 5},       {5, -1},
                            {-16384, 16}, {INT_MIN, 1}, {16385, 1},     {1, 16385},    {16385, 16385},
                            {INT_MAX, 1}, {1, INT_MAX}, {INT_MAX, INT_MAX}, {100000, 100000}};
  for (const auto& wh : refused) {
    const std::string why = Framebuffer::checkSize(wh[0], wh[1]);
    EXPECT_FALSE(why.empty()) << wh[0] << "x" << wh[1];
    // The message names the size asked for.
    EXPECT_NE(why.find(std::to_string(wh[0]) + "x" + std::to_string(wh[1])), std::string::npos) << why;
  }
}

TEST(FramebufferSize, ConstructorThrowsFramebufferSizeError) {
  const int refused[][2] = {{0, 1}, {1, 0}, {-1, -1}, {16385, 1}, {1, 16385}, {INT_MAX, INT_MAX}};
  for (const auto& wh : refused) {
    SCOPED_TRACE(::testing::Message() << wh[0] << "x" << wh[1]);
    EXPECT_THROW(Framebuffer(wh[0], wh[1], indigoProfile()), FramebufferSizeError);
    try {
      Framebuffer fb(wh[0], wh[1], indigoProfile());
      ADD_FAILURE() << "no exception";
    } catch (const FramebufferSizeError& e) {
      EXPECT_EQ(std::string(e.what()), Framebuffer::checkSize(wh[0], wh[1]));
    }
    // It is a std::runtime_error as well.
    EXPECT_THROW(Framebuffer(wh[0], wh[1], mesaProfile()), std::runtime_error);
  }
}

TEST(FramebufferSize, LongThinWindowsAtTheLimitAreAccepted) {
  EXPECT_NO_THROW(Framebuffer(16384, 1, indigoProfile()));
  EXPECT_NO_THROW(Framebuffer(1, 16384, indigoProfile()));
}

TEST(FramebufferSize, UnsupportedProfileWidthsAreRefused) {
  // The stencil is stored in bytes (1..8 bits) and depth in at most 24 bits.
  for (int bits : {0, 9, 16}) {
    HardwareProfile p = indigoProfile();
    p.stencilBits = bits;
    EXPECT_THROW(Framebuffer(2, 2, p), FramebufferSizeError) << "stencil bits " << bits;
  }
  for (int bits : {0, 25, 32}) {
    HardwareProfile p = indigoProfile();
    p.depthBits = bits;
    EXPECT_THROW(Framebuffer(2, 2, p), FramebufferSizeError) << "depth bits " << bits;
  }
  HardwareProfile p = indigoProfile();
  p.stencilBits = 1;
  EXPECT_NO_THROW(Framebuffer(2, 2, p));
}

TEST(FramebufferSize, NewBuffersAreZero) {
  const Framebuffer fb(3, 2, mesaProfile());
  EXPECT_EQ(fb.width(), 3);
  EXPECT_EQ(fb.height(), 2);
  EXPECT_EQ(fb.colorData().size(), 6u);
  EXPECT_EQ(fb.depthData().size(), 6u);
  EXPECT_EQ(fb.stencilData().size(), 6u);
  EXPECT_EQ(fb.accumData().size(), 24u);  // four words per pixel
  for (const Rgba8& c : fb.colorData()) EXPECT_EQ(c, (Rgba8{0, 0, 0, 0}));
  for (std::uint32_t d : fb.depthData()) EXPECT_EQ(d, 0u);
  for (std::int16_t a : fb.accumData()) EXPECT_EQ(a, 0);
  EXPECT_TRUE(stencilMatches(fb, 0, 0, ". . .\n. . ."));
}

}  // namespace
}  // namespace mpr
