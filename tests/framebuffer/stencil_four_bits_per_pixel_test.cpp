// A 4-bit stencil profile per pixel: INCR saturates at 15, INVERT is
// 15 - stored, the wraps are modulo 16, and the write mask, value mask and
// reference are taken modulo the width (stencil_per_pixel.hpp says more).
#include <gtest/gtest.h>

#include <cstdint>

#include "framebuffer/compare_func.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "framebuffer/stencil.hpp"
#include "support/stencil_picture.hpp"
#include "tests/framebuffer/stencil_per_pixel.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds),
// where other files' helpers (kStored, frag) would meet these.
namespace mpr::stencil_four_bits_per_pixel_test {
namespace {

using test::stencilMatches;

using stencil_per_pixel::frag;
using stencil_per_pixel::kOps;
using stencil_per_pixel::kPathNames;
using stencil_per_pixel::kPaths;
using stencil_per_pixel::opState;
using stencil_per_pixel::Path;
using stencil_per_pixel::setRow;
using stencil_per_pixel::stencilOnly;

HardwareProfile fourBitStencil() {
  HardwareProfile p = indigoProfile();
  p.name = "indigo-stencil4";
  p.stencilBits = 4;
  return p;
}

TEST(StencilFourBits, ProfileMaxIs15) { EXPECT_EQ(fourBitStencil().stencilMax(), 15u); }

// Stored 0, 1, 7, 8, 14, 15 (the 4-bit analogues of 0, 1, 127, 128, 254,
// 255), ref 9, write mask 0xFF (only its low 4 bits exist):
//   INCR saturates at 15, INVERT is 15 - stored, the wraps are modulo 16.
TEST(StencilFourBits, OpsSaturateAndWrapAt15) {
  for (int p = 0; p < 3; ++p) {
    SCOPED_TRACE(kPathNames[p]);
    Framebuffer fb(6, 8, fourBitStencil());
    for (int k = 0; k < 8; ++k) {
      setRow(fb, 7 - k, {0, 1, 7, 8, 14, 15});
      const FragmentState s = opState(kOps[k], kPaths[p], 0xFF, 9);
      for (int x = 0; x < 6; ++x) processFragment(s, fb, frag(x, 7 - k));
    }
    EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
       .  1  7  8 14 15
       .  .  .  .  .  .
       9  9  9  9  9  9
       1  2  8  9 15 15
       .  .  6  7 13 14
      15 14  8  7  1  .
       1  2  8  9 15  .
      15  .  6  7 13 14
    )"));
  }
}

// The op values themselves stay inside 4 bits (before any write mask):
// INVERT of 5 = 0101 is 1010 = 10, not 250; the wraps are modulo 16.
TEST(StencilFourBits, OpValuesStayWithinTheWidth) {
  EXPECT_EQ(stencilOpValue(StencilOp::Invert, 5, 0, 15), 10u);
  EXPECT_EQ(stencilOpValue(StencilOp::Invert, 0, 0, 15), 15u);
  EXPECT_EQ(stencilOpValue(StencilOp::Incr, 15, 0, 15), 15u);
  EXPECT_EQ(stencilOpValue(StencilOp::IncrWrap, 15, 0, 15), 0u);
  EXPECT_EQ(stencilOpValue(StencilOp::Decr, 0, 0, 15), 0u);
  EXPECT_EQ(stencilOpValue(StencilOp::DecrWrap, 0, 0, 15), 15u);
  EXPECT_EQ(stencilOpValue(StencilOp::Replace, 3, 9, 15), 9u);
}

TEST(StencilFourBits, IncrRepeatedlyStopsAt15) {
  Framebuffer fb(1, 1, fourBitStencil());
  const FragmentState s = opState(StencilOp::Incr, Path::Dppass, ~0u, 0);
  for (int i = 0; i < 40; ++i) processFragment(s, fb, frag(0, 0));
  EXPECT_EQ(fb.stencil(0, 0), 15);  // not 40, not 255
}

TEST(StencilFourBits, WriteMaskTakenModuloWidth) {
  // Write mask 0xF0 has no bit inside a 4-bit stencil: nothing changes.
  // Write mask 0x13 acts as 0x3. INVERT on 0, 1, 7, 8, 14, 15 computes
  // 15, 14, 8, 7, 1, 0; keeping bits 0xC of the stored value:
  //   0 -> 0|3 = 3, 1 -> 0|2 = 2, 7 -> 4|0 = 4, 8 -> 8|3 = 11, 14 -> 12|1 = 13, 15 -> 12|0 = 12.
  Framebuffer fb(6, 2, fourBitStencil());
  setRow(fb, 1, {0, 1, 7, 8, 14, 15});
  setRow(fb, 0, {0, 1, 7, 8, 14, 15});
  const FragmentState high = opState(StencilOp::Invert, Path::Dppass, 0xF0, 0);
  const FragmentState low = opState(StencilOp::Invert, Path::Dppass, 0x13, 0);
  for (int x = 0; x < 6; ++x) {
    processFragment(high, fb, frag(x, 1));
    processFragment(low, fb, frag(x, 0));
  }
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    .  1  7  8 14 15
    3  2  4 11 13 12
  )"));
}

TEST(StencilFourBits, ValueMaskTakenModuloWidth) {
  // Stored 4, 7, 8, 3. Value mask 0xF0: no bit inside 4 bits, so both sides
  // are 0: EQUAL passes everywhere, LESS nowhere.
  // Value mask 0x1C acts as 0xC. ref 5 & 0xC = 4; stored & 0xC = 4, 4, 8, 0:
  // LESS (4 < s) passes only on 8; EQUAL on 4 and 7; GREATER only on 3.
  const std::vector<int> stored = {4, 7, 8, 3};
  struct Case {
    CompareFunc f;
    unsigned mask;
    std::array<bool, 4> pass;
  };
  const std::array<Case, 5> cases = {{
      {CompareFunc::Equal, 0xF0, {true, true, true, true}},
      {CompareFunc::Less, 0xF0, {false, false, false, false}},
      {CompareFunc::Less, 0x1C, {false, false, true, false}},
      {CompareFunc::Equal, 0x1C, {true, true, false, false}},
      {CompareFunc::Greater, 0x1C, {false, false, false, true}},
  }};
  for (const Case& c : cases) {
    Framebuffer fb(4, 1, fourBitStencil());
    setRow(fb, 0, stored);
    const FragmentState s = stencilOnly(c.f, 5, c.mask);
    for (int x = 0; x < 4; ++x)
      EXPECT_EQ(processFragment(s, fb, frag(x, 0)),
                c.pass[x] ? FragmentFate::Written : FragmentFate::StencilFailed)
          << "mask 0x" << std::hex << c.mask << std::dec << " stored " << stored[x];
  }
}

TEST(StencilFourBits, RefAtMaximum) {
  // ref 15 (the clamped maximum): GEQUAL passes on every 4-bit value,
  // GREATER on all but 15.
  Framebuffer fb(4, 1, fourBitStencil());
  setRow(fb, 0, {0, 8, 14, 15});
  const std::array<bool, 4> greater = {true, true, true, false};
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(processFragment(stencilOnly(CompareFunc::Gequal, 15, 0xFF), fb, frag(x, 0)),
              FragmentFate::Written);
    EXPECT_EQ(processFragment(stencilOnly(CompareFunc::Greater, 15, 0xFF), fb, frag(x, 0)),
              greater[x] ? FragmentFate::Written : FragmentFate::StencilFailed);
  }
}

}  // namespace
}  // namespace mpr::stencil_four_bits_per_pixel_test
