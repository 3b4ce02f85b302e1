// The stencil test per pixel: "(ref & mask) FUNC (stored & mask)", the
// reference on the left, so GL_GREATER passes when ref > stored (GL 1.1
// section 4.1.4), against truth tables written by hand and an independent
// reference formula (stencil_per_pixel.hpp says more).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "framebuffer/compare_func.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "framebuffer/stencil.hpp"
#include "support/compare_funcs.hpp"
#include "support/stencil_picture.hpp"
#include "tests/framebuffer/stencil_per_pixel.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds),
// where other files' helpers (kStored, frag) would meet these.
namespace mpr::stencil_func_per_pixel_test {
namespace {

using test::stencilMatches;

using test::kFuncNames;
using test::kFuncs;

using stencil_per_pixel::frag;
using stencil_per_pixel::setRow;
using stencil_per_pixel::stencilOnly;

// Independent reference for the stencil test, from the GL text. For each
// function: does it pass when (ref & mask) is less than, equal to, greater
// than (stored & mask)?
struct FuncTruth {
  bool less, equal, greater;
};
constexpr std::array<FuncTruth, 8> kFuncTruth = {{
    {false, false, false},  // NEVER
    {true, false, false},   // LESS:     ref <  stored
    {false, true, false},   // EQUAL:    ref == stored
    {true, true, false},    // LEQUAL:   ref <= stored
    {false, false, true},   // GREATER:  ref >  stored
    {true, false, true},    // NOTEQUAL: ref != stored
    {false, true, true},    // GEQUAL:   ref >= stored
    {true, true, true},     // ALWAYS
}};

bool referencePasses(int funcIndex, unsigned ref, unsigned mask, unsigned stored) {
  const unsigned a = ref & mask, b = stored & mask;
  const FuncTruth& t = kFuncTruth[funcIndex];
  return a < b ? t.less : (a == b ? t.equal : t.greater);
}

// Hand-written rows: ref = 128, mask = 0xFF, stored 0, 127, 128, 129, 255.
// GREATER passes where 128 > stored, i.e. on 0 and 127 (not "stored greater
// than ref", the paper's wording).
TEST(StencilFunc, HandTruthTableRef128FullMask) {
  const std::vector<int> stored = {0, 127, 128, 129, 255};
  const std::array<std::vector<bool>, 8> expected = {{
      {false, false, false, false, false},  // NEVER
      {false, false, false, true, true},    // LESS:     128 < 129, 255
      {false, false, true, false, false},   // EQUAL:    128 == 128
      {false, false, true, true, true},     // LEQUAL
      {true, true, false, false, false},    // GREATER:  128 > 0, 127
      {true, true, false, true, true},      // NOTEQUAL
      {true, true, true, false, false},     // GEQUAL
      {true, true, true, true, true},       // ALWAYS
  }};
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(kFuncNames[f]);
    Framebuffer fb(5, 1, indigoProfile());
    setRow(fb, 0, stored);
    const FragmentState s = stencilOnly(kFuncs[f], 128, 0xFF);
    for (int x = 0; x < 5; ++x) {
      const FragmentFate fate = processFragment(s, fb, frag(x, 0));
      EXPECT_EQ(fate, expected[f][x] ? FragmentFate::Written : FragmentFate::StencilFailed)
          << "stored " << stored[x];
      // A passing fragment writes its colour, a failing one leaves black.
      EXPECT_EQ(fb.color(x, 0), expected[f][x] ? (Rgba8{10, 20, 30, 40}) : (Rgba8{0, 0, 0, 0}));
    }
    // KEEP everywhere: the stencil never changes.
    EXPECT_TRUE(stencilMatches(fb, 0, 0, ". 127 128 129 255"));
  }
}

// ref = 0x35 (53), mask = 0x0F: the masked reference is 5. Stored values
// 0x05, 0xF5, 0x04, 0x16, 0x50 mask to 5, 5, 4, 6, 0, so the reference is
// equal, equal, greater, less, greater.
TEST(StencilFunc, HandTruthTableMaskedLowNibble) {
  const std::vector<int> stored = {0x05, 0xF5, 0x04, 0x16, 0x50};
  const std::array<std::vector<bool>, 8> expected = {{
      {false, false, false, false, false},  // NEVER
      {false, false, false, true, false},   // LESS: 5 < 6 only
      {true, true, false, false, false},    // EQUAL
      {true, true, false, true, false},     // LEQUAL
      {false, false, true, false, true},    // GREATER: 5 > 4, 5 > 0
      {false, false, true, true, true},     // NOTEQUAL
      {true, true, true, false, true},      // GEQUAL
      {true, true, true, true, true},       // ALWAYS
  }};
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(kFuncNames[f]);
    Framebuffer fb(5, 1, indigoProfile());
    setRow(fb, 0, stored);
    const FragmentState s = stencilOnly(kFuncs[f], 0x35, 0x0F);
    for (int x = 0; x < 5; ++x)
      EXPECT_EQ(processFragment(s, fb, frag(x, 0)),
                expected[f][x] ? FragmentFate::Written : FragmentFate::StencilFailed)
          << "stored " << stored[x];
  }
}

// mask = 0: both sides are 0, so EQUAL, LEQUAL, GEQUAL, ALWAYS pass and the
// others fail whatever ref and stored are.
TEST(StencilFunc, ZeroMaskComparesZeroWithZero) {
  const std::array<bool, 8> passes = {false, false, true, true, false, false, true, true};
  for (int f = 0; f < 8; ++f) {
    SCOPED_TRACE(kFuncNames[f]);
    Framebuffer fb(4, 1, indigoProfile());
    setRow(fb, 0, {0, 1, 200, 255});
    const FragmentState s = stencilOnly(kFuncs[f], 200, 0x00);
    for (int x = 0; x < 4; ++x)
      EXPECT_EQ(processFragment(s, fb, frag(x, 0)),
                passes[f] ? FragmentFate::Written : FragmentFate::StencilFailed);
  }
}

// Every function x every reference x a family of value masks, on a 16x16
// window holding every stored value 0..255 once (stored = x + 16 y), against
// the independent reference formula.
TEST(StencilFunc, EveryFunctionRefAndMaskPerPixel) {
  const std::array<unsigned, 14> masks = {0xFF, 0x00, 0x0F, 0xF0, 0x01, 0x02, 0x04,
                                          0x08, 0x10, 0x20, 0x40, 0x80, 0xAA, 0x7F};
  Framebuffer fb(16, 16, indigoProfile());
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) fb.stencil(x, y) = static_cast<std::uint8_t>(x + 16 * y);
  long checked = 0, wrong = 0;
  for (int f = 0; f < 8; ++f)
    for (unsigned mask : masks)
      for (unsigned ref = 0; ref < 256; ++ref) {
        const FragmentState s = stencilOnly(kFuncs[f], ref, mask);
        for (int y = 0; y < 16; ++y)
          for (int x = 0; x < 16; ++x) {
            const unsigned stored = static_cast<unsigned>(x + 16 * y);
            const bool want = referencePasses(f, ref, mask, stored);
            const FragmentFate got = processFragment(s, fb, frag(x, y));
            ++checked;
            if (got != (want ? FragmentFate::Written : FragmentFate::StencilFailed) && ++wrong <= 10)
              ADD_FAILURE() << kFuncNames[f] << " ref " << ref << " mask 0x" << std::hex << mask
                            << std::dec << " stored " << stored << ": expected "
                            << (want ? "pass" : "fail");
          }
      }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(checked, 8L * 14 * 256 * 256);
  // KEEP throughout: the 256 stored values are intact (spot-check corners).
  EXPECT_EQ(fb.stencil(0, 0), 0);
  EXPECT_EQ(fb.stencil(15, 15), 255);
}

// The same reference over every mask 0..255 (stencilTest alone, 8 x 2^24 cases).
TEST(StencilFunc, StencilTestMatchesReferenceForEveryMask) {
  long wrong = 0;
  for (int f = 0; f < 8; ++f)
    for (unsigned mask = 0; mask < 256; ++mask)
      for (unsigned ref = 0; ref < 256; ++ref) {
        StencilState s;
        s.enabled = true;
        s.func = kFuncs[f];
        s.ref = ref;
        s.valueMask = mask;
        for (unsigned stored = 0; stored < 256; ++stored)
          if (stencilTest(s, stored) != referencePasses(f, ref, mask, stored) && ++wrong <= 10)
            ADD_FAILURE() << kFuncNames[f] << " ref " << ref << " mask " << mask << " stored " << stored;
      }
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace mpr::stencil_func_per_pixel_test
