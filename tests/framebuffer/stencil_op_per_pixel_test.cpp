// The stencil operations per pixel: KEEP, ZERO, REPLACE, INCR / DECR
// saturating, INVERT within the width, INCR_WRAP / DECR_WRAP (GL 1.1
// section 4.1.4 and EXT_stencil_wrap), each through sfail, dpfail and
// dppass, under full, empty, nibble and single-bit write masks, against
// tables written by hand (stencil_per_pixel.hpp says more).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "framebuffer/stencil.hpp"
#include "support/stencil_picture.hpp"
#include "tests/framebuffer/stencil_per_pixel.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds),
// where other files' helpers (kStored, frag) would meet these.
namespace mpr::stencil_op_per_pixel_test {
namespace {

using test::stencilMatches;

using stencil_per_pixel::frag;
using stencil_per_pixel::kOpNames;
using stencil_per_pixel::kOps;
using stencil_per_pixel::kPathNames;
using stencil_per_pixel::kPaths;
using stencil_per_pixel::opState;
using stencil_per_pixel::Path;
using stencil_per_pixel::setRow;

// The stored values every op table starts from.
const std::vector<int> kStored = {0, 1, 127, 128, 254, 255};
constexpr std::uint32_t kRef = 0x5A;  // 90, for REPLACE

// What each op computes on kStored before the write mask (8 bits), by hand:
const std::array<std::vector<int>, 8> kOpValue = {{
    {0, 1, 127, 128, 254, 255},    // KEEP
    {0, 0, 0, 0, 0, 0},            // ZERO
    {90, 90, 90, 90, 90, 90},      // REPLACE by 0x5A
    {1, 2, 128, 129, 255, 255},    // INCR, saturating at 255
    {0, 0, 126, 127, 253, 254},    // DECR, saturating at 0
    {255, 254, 128, 127, 1, 0},    // INVERT: 255 - stored
    {1, 2, 128, 129, 255, 0},      // INCR_WRAP: 255 + 1 -> 0
    {255, 0, 126, 127, 253, 254},  // DECR_WRAP: 0 - 1 -> 255
}};

// A 6x8 window: row y = 7 - k starts as kStored and receives op k, so the
// picture reads KEEP at the top down to DECR_WRAP at the bottom.
Framebuffer applyOpTable(Path path, std::uint32_t writeMask) {
  Framebuffer fb(6, 8, indigoProfile());
  for (int k = 0; k < 8; ++k) {
    const int y = 7 - k;
    setRow(fb, y, kStored);
    const FragmentState s = opState(kOps[k], path, writeMask, kRef);
    for (int x = 0; x < 6; ++x) processFragment(s, fb, frag(x, y));
  }
  return fb;
}

TEST(StencilOp, FullWriteMask) {
  for (int p = 0; p < 3; ++p) {
    SCOPED_TRACE(kPathNames[p]);
    const Framebuffer fb = applyOpTable(kPaths[p], 0xFF);
    EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
        .   1 127 128 254 255
        .   .   .   .   .   .
       90  90  90  90  90  90
        1   2 128 129 255 255
        .   . 126 127 253 254
      255 254 128 127   1   .
        1   2 128 129 255   .
      255   . 126 127 253 254
    )"));
  }
}

// Write mask 0: nothing changes, whatever the op.
TEST(StencilOp, ZeroWriteMaskKeepsEverything) {
  for (int p = 0; p < 3; ++p) {
    SCOPED_TRACE(kPathNames[p]);
    const Framebuffer fb = applyOpTable(kPaths[p], 0x00);
    EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
        .   1 127 128 254 255
        .   1 127 128 254 255
        .   1 127 128 254 255
        .   1 127 128 254 255
        .   1 127 128 254 255
        .   1 127 128 254 255
        .   1 127 128 254 255
        .   1 127 128 254 255
    )"));
  }
}

// Write mask 0x0F: the high nibble of the stored value stays, the low nibble
// is the op's. E.g. DECR on 128 = 0x80 computes 0x7F; 0x80 | 0xF = 143.
// INVERT on 254 = 0xFE computes 0x01: 0xF0 | 0x1 = 241.
TEST(StencilOp, LowNibbleWriteMask) {
  for (int p = 0; p < 3; ++p) {
    SCOPED_TRACE(kPathNames[p]);
    const Framebuffer fb = applyOpTable(kPaths[p], 0x0F);
    EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
        .   1 127 128 254 255
        .   . 112 128 240 240
       10  10 122 138 250 250
        1   2 112 129 255 255
        .   . 126 143 253 254
       15  14 112 143 241 240
        1   2 112 129 255 240
       15   . 126 143 253 254
    )"));
  }
}

// Write mask 0xF0: the low nibble of the stored value stays, the high nibble
// is the op's. E.g. INCR on 127 = 0x7F computes 0x80: 0x80 | 0xF = 143;
// REPLACE by 0x5A on 254 = 0xFE: 0x50 | 0xE = 94.
TEST(StencilOp, HighNibbleWriteMask) {
  for (int p = 0; p < 3; ++p) {
    SCOPED_TRACE(kPathNames[p]);
    const Framebuffer fb = applyOpTable(kPaths[p], 0xF0);
    EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
        .   1 127 128 254 255
        .   1  15   .  14  15
       80  81  95  80  94  95
        .   1 143 128 254 255
        .   1 127 112 254 255
      240 241 143 112  14  15
        .   1 143 128 254  15
      240   1 127 112 254 255
    )"));
  }
}

// Single-bit write masks: bit b of the result is bit b of the op's value (from
// the hand table kOpValue), every other bit is the stored one.
TEST(StencilOp, SingleBitWriteMasks) {
  for (int p = 0; p < 3; ++p)
    for (int b = 0; b < 8; ++b) {
      const unsigned m = 1u << b;
      SCOPED_TRACE(std::string(kPathNames[p]) + " write mask bit " + std::to_string(b));
      const Framebuffer fb = applyOpTable(kPaths[p], m);
      for (int k = 0; k < 8; ++k)
        for (int x = 0; x < 6; ++x) {
          const unsigned stored = static_cast<unsigned>(kStored[x]);
          const unsigned want = (stored & ~m & 0xFFu) | (static_cast<unsigned>(kOpValue[k][x]) & m);
          EXPECT_EQ(fb.stencil(x, 7 - k), want) << kOpNames[k] << " on " << stored;
        }
    }
}

TEST(StencilOp, IncrSaturatesAt255AndDecrAt0) {
  Framebuffer fb(2, 1, indigoProfile());
  setRow(fb, 0, {252, 3});
  FragmentState incr = opState(StencilOp::Incr, Path::Dppass, 0xFF, 0);
  FragmentState decr = opState(StencilOp::Decr, Path::Dppass, 0xFF, 0);
  // 252 -> 253 -> 254 -> 255 -> 255 -> 255; 3 -> 2 -> 1 -> 0 -> 0 -> 0.
  const std::array<int, 5> up = {253, 254, 255, 255, 255};
  const std::array<int, 5> down = {2, 1, 0, 0, 0};
  for (int i = 0; i < 5; ++i) {
    processFragment(incr, fb, frag(0, 0));
    processFragment(decr, fb, frag(1, 0));
    EXPECT_EQ(fb.stencil(0, 0), up[i]) << "after " << i + 1 << " INCR";
    EXPECT_EQ(fb.stencil(1, 0), down[i]) << "after " << i + 1 << " DECR";
  }
  // Many more: still pinned.
  for (int i = 0; i < 300; ++i) {
    processFragment(incr, fb, frag(0, 0));
    processFragment(decr, fb, frag(1, 0));
  }
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "255 ."));
}

TEST(StencilOp, IncrWrapAndDecrWrapWrapAround) {
  Framebuffer fb(2, 1, indigoProfile());
  setRow(fb, 0, {254, 1});
  FragmentState incr = opState(StencilOp::IncrWrap, Path::Dppass, 0xFF, 0);
  FragmentState decr = opState(StencilOp::DecrWrap, Path::Dppass, 0xFF, 0);
  // 254 -> 255 -> 0 -> 1; 1 -> 0 -> 255 -> 254.
  const std::array<int, 3> up = {255, 0, 1};
  const std::array<int, 3> down = {0, 255, 254};
  for (int i = 0; i < 3; ++i) {
    processFragment(incr, fb, frag(0, 0));
    processFragment(decr, fb, frag(1, 0));
    EXPECT_EQ(fb.stencil(0, 0), up[i]);
    EXPECT_EQ(fb.stencil(1, 0), down[i]);
  }
  // 256 more INCR_WRAPs return to where they started (1); 256 DECR_WRAPs too (254).
  for (int i = 0; i < 256; ++i) {
    processFragment(incr, fb, frag(0, 0));
    processFragment(decr, fb, frag(1, 0));
  }
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "1 254"));
}

// The op functions themselves, a few cases by hand (8-bit max 255).
TEST(StencilOp, OpValueAndApplyDirectly) {
  EXPECT_EQ(stencilOpValue(StencilOp::Incr, 255, 0, 255), 255u);
  EXPECT_EQ(stencilOpValue(StencilOp::IncrWrap, 255, 0, 255), 0u);
  EXPECT_EQ(stencilOpValue(StencilOp::Decr, 0, 0, 255), 0u);
  EXPECT_EQ(stencilOpValue(StencilOp::DecrWrap, 0, 0, 255), 255u);
  EXPECT_EQ(stencilOpValue(StencilOp::Invert, 0x5A, 0, 255), 0xA5u);
  EXPECT_EQ(stencilOpValue(StencilOp::Replace, 7, 0xC3, 255), 0xC3u);
  StencilState s;
  s.ref = 0xC3;
  s.writeMask = 0x3C;
  // REPLACE 0xC3 through mask 0x3C onto 0x5A: (0x5A & 0xC3) | (0xC3 & 0x3C) = 0x42 | 0x00 = 0x42.
  EXPECT_EQ(applyStencilOp(StencilOp::Replace, 0x5A, s, 255), 0x42u);
  // INVERT through 0x3C onto 0x5A: ~0x5A = 0xA5; (0x42) | (0xA5 & 0x3C = 0x24) = 0x66.
  EXPECT_EQ(applyStencilOp(StencilOp::Invert, 0x5A, s, 255), 0x66u);
}

}  // namespace
}  // namespace mpr::stencil_op_per_pixel_test
