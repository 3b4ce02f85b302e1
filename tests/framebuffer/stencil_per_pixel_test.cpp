// The stencil test and the stencil operations (GL 1.1 section 4.1.4 and
// EXT_stencil_wrap), checked per pixel through processFragment against truth
// tables written by hand from the GL text:
//   - the test: "(ref & mask) FUNC (stored & mask)", the reference on the left,
//     so GL_GREATER passes when ref > stored;
//   - the operations: KEEP, ZERO, REPLACE (by ref), INCR / DECR saturating at
//     0 and 2^bits - 1, INVERT (bitwise, within the width), INCR_WRAP /
//     DECR_WRAP modulo 2^bits;
//   - the write mask: only the bits set in it are replaced by the op's value;
//   - which op: sfail when the stencil test fails, dpfail when it passes and the
//     depth test fails, dppass when both pass or the depth test is disabled.
// Every expected value below is written out by hand; none is computed by the
// code under test.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/compare_func.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "framebuffer/stencil.hpp"
#include "support/stencil_picture.hpp"
#include "support/compare_funcs.hpp"

namespace mpr {
namespace {

using test::stencilMatches;

using test::kFuncNames;
using test::kFuncs;

constexpr std::array<StencilOp, 8> kOps = {StencilOp::Keep,   StencilOp::Zero,    StencilOp::Replace,
                                           StencilOp::Incr,   StencilOp::Decr,    StencilOp::Invert,
                                           StencilOp::IncrWrap, StencilOp::DecrWrap};
constexpr std::array<const char*, 8> kOpNames = {"KEEP",   "ZERO",   "REPLACE",   "INCR",
                                                 "DECR",   "INVERT", "INCR_WRAP", "DECR_WRAP"};

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

Fragment frag(int x, int y, std::uint32_t depth = 0x800000) {
  return Fragment{x, y, depth, Rgba8{10, 20, 30, 40}, 1.0f};
}

// A state that only runs the stencil test: no alpha, depth or blending.
FragmentState stencilOnly(CompareFunc f, std::uint32_t ref, std::uint32_t valueMask) {
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.func = f;
  s.stencil.ref = ref;
  s.stencil.valueMask = valueMask;
  return s;
}

void setRow(Framebuffer& fb, int y, const std::vector<int>& values) {
  for (int x = 0; x < static_cast<int>(values.size()); ++x) fb.stencil(x, y) = static_cast<std::uint8_t>(values[x]);
}

// ---------------------------------------------------------------------------
// The stencil test
// ---------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------
// The stencil operations
// ---------------------------------------------------------------------------

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

// How the op is reached: as sfail, as dpfail or as dppass.
enum class Path { Sfail, Dpfail, Dppass };
constexpr std::array<Path, 3> kPaths = {Path::Sfail, Path::Dpfail, Path::Dppass};
constexpr std::array<const char*, 3> kPathNames = {"sfail", "dpfail", "dppass"};

// A state whose fragments take `op` through `path`; the other two slots hold
// ZERO so that a wrong selection shows.
FragmentState opState(StencilOp op, Path path, std::uint32_t writeMask, std::uint32_t ref) {
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.ref = ref;
  s.stencil.writeMask = writeMask;
  s.stencil.sfail = s.stencil.dpfail = s.stencil.dppass = StencilOp::Zero;
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Always;
  switch (path) {
    case Path::Sfail:
      s.stencil.func = CompareFunc::Never;
      s.stencil.sfail = op;
      break;
    case Path::Dpfail:
      s.stencil.func = CompareFunc::Always;
      s.depth.func = CompareFunc::Never;
      s.stencil.dpfail = op;
      break;
    case Path::Dppass:
      s.stencil.func = CompareFunc::Always;
      s.stencil.dppass = op;
      break;
  }
  return s;
}

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

// ---------------------------------------------------------------------------
// sfail / dpfail / dppass selection
// ---------------------------------------------------------------------------

// sfail = INVERT, dpfail = INCR, dppass = DECR: from 10 they give 245, 11 and 9.
FragmentState selectionState() {
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.func = CompareFunc::Equal;
  s.stencil.ref = 10;
  s.stencil.valueMask = 0xFF;
  s.stencil.sfail = StencilOp::Invert;
  s.stencil.dpfail = StencilOp::Incr;
  s.stencil.dppass = StencilOp::Decr;
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Less;
  return s;
}

TEST(StencilSelection, SfailDpfailDppass) {
  // x = 0: stored 11, EQUAL 10 fails -> sfail INVERT: 255 - 11 = 244.
  // x = 1: stored 10, stencil passes; fragment depth 500 not < stored 400 -> dpfail INCR: 11.
  // x = 2: stored 10, stencil passes; 300 < 400 -> dppass DECR: 9.
  Framebuffer fb(3, 1, indigoProfile());
  setRow(fb, 0, {11, 10, 10});
  for (int x = 0; x < 3; ++x) fb.depth(x, 0) = 400;
  const FragmentState s = selectionState();
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 300)), FragmentFate::StencilFailed);
  EXPECT_EQ(processFragment(s, fb, frag(1, 0, 500)), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(s, fb, frag(2, 0, 300)), FragmentFate::Written);
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "244 11 9"));
  // Only the passing fragment wrote depth.
  EXPECT_EQ(fb.depth(0, 0), 400u);
  EXPECT_EQ(fb.depth(1, 0), 400u);
  EXPECT_EQ(fb.depth(2, 0), 300u);
}

TEST(StencilSelection, DepthTestDisabledTakesDppass) {
  // With the depth test disabled the depth comparison cannot fail: even a
  // fragment "behind" the stored depth, and a depth func of NEVER, take dppass.
  Framebuffer fb(3, 1, indigoProfile());
  setRow(fb, 0, {11, 10, 10});
  for (int x = 0; x < 3; ++x) fb.depth(x, 0) = 400;
  FragmentState s = selectionState();
  s.depth.enabled = false;
  s.depth.func = CompareFunc::Never;
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 300)), FragmentFate::StencilFailed);  // 11 -> 244
  EXPECT_EQ(processFragment(s, fb, frag(1, 0, 500)), FragmentFate::Written);        // 10 -> 9
  EXPECT_EQ(processFragment(s, fb, frag(2, 0, 300)), FragmentFate::Written);        // 10 -> 9
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "244 9 9"));
}

TEST(StencilSelection, StencilTestDisabledLeavesStencilUntouched) {
  // Same three fragments, stencil test off: no op runs, the stored values
  // stay 11 10 10 although every op and the write mask would change them.
  Framebuffer fb(3, 1, indigoProfile());
  setRow(fb, 0, {11, 10, 10});
  for (int x = 0; x < 3; ++x) fb.depth(x, 0) = 400;
  FragmentState s = selectionState();
  s.stencil.enabled = false;
  s.stencil.func = CompareFunc::Never;  // would fail every fragment if enabled
  EXPECT_EQ(processFragment(s, fb, frag(0, 0, 300)), FragmentFate::Written);
  EXPECT_EQ(processFragment(s, fb, frag(1, 0, 500)), FragmentFate::DepthFailed);
  EXPECT_EQ(processFragment(s, fb, frag(2, 0, 300)), FragmentFate::Written);
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "11 10 10"));
  // And with the depth test off as well.
  s.depth.enabled = false;
  for (int x = 0; x < 3; ++x) processFragment(s, fb, frag(x, 0, 999));
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "11 10 10"));
}

TEST(StencilSelection, WriteMaskAppliesToEverySlot) {
  // Write mask 0xF0 on stored 0x0A (10) with sfail INVERT (0xF5), dpfail
  // INCR (0x0B), dppass DECR (0x09): the low nibble A stays in all three,
  // the high nibble becomes F, 0, 0: 0xFA = 250, 0x0A = 10, 0x0A = 10.
  Framebuffer fb(3, 1, indigoProfile());
  setRow(fb, 0, {10, 10, 10});
  for (int x = 0; x < 3; ++x) fb.depth(x, 0) = 400;
  FragmentState s = selectionState();
  s.stencil.writeMask = 0xF0;
  s.stencil.func = CompareFunc::Notequal;  // stored 10 == ref 10 fails
  processFragment(s, fb, frag(0, 0, 300));
  s.stencil.func = CompareFunc::Equal;
  processFragment(s, fb, frag(1, 0, 500));
  processFragment(s, fb, frag(2, 0, 300));
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "250 10 10"));
}

// ---------------------------------------------------------------------------
// A 4-bit stencil profile: saturation at 15, masks modulo 16
// ---------------------------------------------------------------------------

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
}  // namespace mpr
