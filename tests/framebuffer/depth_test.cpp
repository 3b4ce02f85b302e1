// The depth buffer test (GL 1.1 section 4.1.5) per pixel through
// processFragment: the eight functions with the incoming depth less than,
// equal to and greater than the stored one ("incoming FUNC stored"), the depth
// write mask, the disabled test (no comparison and no depth write), and the
// extremes of the 24-bit range. Expected values are written by hand.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "framebuffer/clear.hpp"
#include "framebuffer/compare_func.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "support/compare_funcs.hpp"

namespace mpr {
namespace {

using test::kFuncNames;
using test::kFuncs;

// Does each function pass when the incoming depth is less than, equal to,
// greater than the stored depth? (GL: incoming on the left.)
struct Truth {
  bool less, equal, greater;
};
constexpr std::array<Truth, 8> kTruth = {{
    {false, false, false},  // NEVER
    {true, false, false},   // LESS
    {false, true, false},   // EQUAL
    {true, true, false},    // LEQUAL
    {false, false, true},   // GREATER
    {true, false, true},    // NOTEQUAL
    {false, true, true},    // GEQUAL
    {true, true, true},     // ALWAYS
}};

constexpr Rgba8 kSrc{11, 22, 33, 44};
constexpr Rgba8 kBlack{0, 0, 0, 0};

FragmentState depthOnly(CompareFunc f, bool writeMask = true) {
  FragmentState s;
  s.depth.enabled = true;
  s.depth.func = f;
  s.depth.writeMask = writeMask;
  return s;
}

Fragment frag(int x, int y, std::uint32_t depth, Rgba8 c = kSrc) { return Fragment{x, y, depth, c, 1.0f}; }

// Three pixels, every fragment at depth 0x800000 (the middle of 24 bits):
//   x = 0 stores 0x800001 -> incoming is less,
//   x = 1 stores 0x800000 -> equal,
//   x = 2 stores 0x7FFFFF -> incoming is greater.
constexpr std::array<std::uint32_t, 3> kStored = {0x800001, 0x800000, 0x7FFFFF};
constexpr std::uint32_t kIncoming = 0x800000;

Framebuffer threePixels() {
  Framebuffer fb(3, 1, indigoProfile());
  for (int x = 0; x < 3; ++x) fb.depth(x, 0) = kStored[x];
  return fb;
}

TEST(DepthFunc, EveryFunctionAtLessEqualGreater) {
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(kFuncNames[f]);
    Framebuffer fb = threePixels();
    const FragmentState s = depthOnly(kFuncs[f]);
    const std::array<bool, 3> pass = {kTruth[f].less, kTruth[f].equal, kTruth[f].greater};
    for (int x = 0; x < 3; ++x) {
      EXPECT_EQ(processFragment(s, fb, frag(x, 0, kIncoming)),
                pass[x] ? FragmentFate::Written : FragmentFate::DepthFailed);
      // A passing fragment stores its depth and colour; a failing one neither.
      EXPECT_EQ(fb.depth(x, 0), pass[x] ? kIncoming : kStored[x]) << "x " << x;
      EXPECT_EQ(fb.color(x, 0), pass[x] ? kSrc : kBlack) << "x " << x;
    }
  }
}

// The same table, written out as the depth words each pixel ends with.
TEST(DepthFunc, StoredWordsByHand) {
  // x:                0         1         2
  const std::array<std::array<std::uint32_t, 3>, 8> after = {{
      {0x800001, 0x800000, 0x7FFFFF},  // NEVER: nothing changes
      {0x800000, 0x800000, 0x7FFFFF},  // LESS: x = 0 only
      {0x800001, 0x800000, 0x7FFFFF},  // EQUAL: x = 1 (rewrites the same word)
      {0x800000, 0x800000, 0x7FFFFF},  // LEQUAL: x = 0, 1
      {0x800001, 0x800000, 0x800000},  // GREATER: x = 2 only
      {0x800000, 0x800000, 0x800000},  // NOTEQUAL: x = 0, 2
      {0x800001, 0x800000, 0x800000},  // GEQUAL: x = 1, 2
      {0x800000, 0x800000, 0x800000},  // ALWAYS
  }};
  for (int f = 0; f < 8; ++f) {
    Framebuffer fb = threePixels();
    for (int x = 0; x < 3; ++x) processFragment(depthOnly(kFuncs[f]), fb, frag(x, 0, kIncoming));
    for (int x = 0; x < 3; ++x) EXPECT_EQ(fb.depth(x, 0), after[f][x]) << kFuncNames[f] << " x " << x;
  }
}

TEST(DepthWrite, MaskOffTestsButDoesNotWrite) {
  // Depth write mask off: the comparison still decides the colour, but no
  // depth word changes.
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(kFuncNames[f]);
    Framebuffer fb = threePixels();
    const FragmentState s = depthOnly(kFuncs[f], /*writeMask=*/false);
    const std::array<bool, 3> pass = {kTruth[f].less, kTruth[f].equal, kTruth[f].greater};
    for (int x = 0; x < 3; ++x) {
      EXPECT_EQ(processFragment(s, fb, frag(x, 0, kIncoming)),
                pass[x] ? FragmentFate::Written : FragmentFate::DepthFailed);
      EXPECT_EQ(fb.depth(x, 0), kStored[x]);
      EXPECT_EQ(fb.color(x, 0), pass[x] ? kSrc : kBlack);
    }
  }
}

TEST(DepthWrite, DisabledTestWritesNoDepth) {
  // GL 1.1: with the depth test disabled the comparison and the depth update
  // are bypassed. Every fragment is written (even with func NEVER) and no
  // depth word changes (even with the write mask on).
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(kFuncNames[f]);
    Framebuffer fb = threePixels();
    FragmentState s = depthOnly(kFuncs[f], /*writeMask=*/true);
    s.depth.enabled = false;
    for (int x = 0; x < 3; ++x) {
      EXPECT_EQ(processFragment(s, fb, frag(x, 0, 0x123456)), FragmentFate::Written);
      EXPECT_EQ(fb.depth(x, 0), kStored[x]);
      EXPECT_EQ(fb.color(x, 0), kSrc);
    }
  }
}

TEST(DepthFunc, ZBufferSequenceKeepsNearest) {
  // LESS: 0x300000 passes (< 0xFFFFFF), 0x400000 fails (not < 0x300000),
  // 0x200000 passes: the pixel ends at 0x200000 with the third colour.
  Framebuffer fb(1, 1, indigoProfile());
  fb.depth(0, 0) = 0xFFFFFF;
  const FragmentState s = depthOnly(CompareFunc::Less);
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 0x300000, Rgba8{1, 0, 0, 255})), FragmentFate::Written);
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 0x400000, Rgba8{0, 2, 0, 255})), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 0x200000, Rgba8{0, 0, 3, 255})), FragmentFate::Written);
  EXPECT_EQ(fb.depth(0, 0), 0x200000u);
  EXPECT_EQ(fb.color(0, 0), (Rgba8{0, 0, 3, 255}));
}

// ---------------------------------------------------------------------------
// 24-bit extremes
// ---------------------------------------------------------------------------

TEST(DepthExtremes, ProfileMaxIs24Bits) {
  EXPECT_EQ(indigoProfile().depthBits, 24);
  EXPECT_EQ(indigoProfile().depthMax(), 0xFFFFFFu);  // 2^24 - 1 = 16777215
  EXPECT_EQ(mesaProfile().depthMax(), 16777215u);
}

TEST(DepthExtremes, FarPlane) {
  // Stored 0xFFFFFF (cleared to the far plane) on all four pixels:
  //   x = 0: 0xFFFFFF LESS    -> fails (equal)
  //   x = 1: 0xFFFFFF LEQUAL  -> passes, stores 0xFFFFFF
  //   x = 2: 0xFFFFFE LESS    -> passes by one unit
  //   x = 3: 0        LESS    -> passes, stores 0
  Framebuffer fb(4, 1, indigoProfile());
  ClearValues v;
  v.depth = 0xFFFFFF;
  ClearBuffers which;
  which.depth = true;
  clearBuffers(fb, fb.bounds(), which, v, ClearMasks{});
  for (int x = 0; x < 4; ++x) ASSERT_EQ(fb.depth(x, 0), 0xFFFFFFu);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Less), fb, frag(0, 0, 0xFFFFFF)), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Lequal), fb, frag(1, 0, 0xFFFFFF)), FragmentFate::Written);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Less), fb, frag(2, 0, 0xFFFFFE)), FragmentFate::Written);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Less), fb, frag(3, 0, 0)), FragmentFate::Written);
  EXPECT_EQ(fb.depth(0, 0), 0xFFFFFFu);
  EXPECT_EQ(fb.depth(1, 0), 0xFFFFFFu);
  EXPECT_EQ(fb.depth(2, 0), 0xFFFFFEu);
  EXPECT_EQ(fb.depth(3, 0), 0u);
  EXPECT_EQ(fb.color(0, 0), kBlack);
  EXPECT_EQ(fb.color(1, 0), kSrc);
}

TEST(DepthExtremes, NearPlane) {
  // Stored 0 (a new framebuffer is zero) on all four pixels:
  //   x = 0: 0        GREATER -> fails (equal)
  //   x = 1: 0        GEQUAL  -> passes, stores 0
  //   x = 2: 1        GREATER -> passes by one unit
  //   x = 3: 0xFFFFFF GREATER -> passes, stores 0xFFFFFF
  Framebuffer fb(4, 1, indigoProfile());
  for (int x = 0; x < 4; ++x) ASSERT_EQ(fb.depth(x, 0), 0u);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Greater), fb, frag(0, 0, 0)), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Gequal), fb, frag(1, 0, 0)), FragmentFate::Written);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Greater), fb, frag(2, 0, 1)), FragmentFate::Written);
  EXPECT_EQ(processFragment(depthOnly(CompareFunc::Greater), fb, frag(3, 0, 0xFFFFFF)), FragmentFate::Written);
  EXPECT_EQ(fb.depth(0, 0), 0u);
  EXPECT_EQ(fb.depth(1, 0), 0u);
  EXPECT_EQ(fb.depth(2, 0), 1u);
  EXPECT_EQ(fb.depth(3, 0), 0xFFFFFFu);
}

TEST(DepthExtremes, EqualAtBothEnds) {
  // EQUAL distinguishes 0xFFFFFF from 0xFFFFFE and 0 from 1: no rounding.
  Framebuffer fb(4, 1, indigoProfile());
  fb.depth(0, 0) = 0xFFFFFF;
  fb.depth(1, 0) = 0xFFFFFF;
  fb.depth(2, 0) = 0;
  fb.depth(3, 0) = 0;
  const FragmentState s = depthOnly(CompareFunc::Equal);
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 0xFFFFFF)), FragmentFate::Written);
  EXPECT_EQ(processFragment(s, fb, frag(1, 0, 0xFFFFFE)), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(s, fb, frag(2, 0, 0)), FragmentFate::Written);
  EXPECT_EQ(processFragment(s, fb, frag(3, 0, 1)), FragmentFate::DepthFailed);
}

}  // namespace
}  // namespace mpr
