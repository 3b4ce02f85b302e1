// The stencil test and operations, per pixel and exactly: every function x
// reference x value mask, every operation x write mask family, saturation and
// wrap at the profile's width, and the choice among sfail / dpfail / dppass.
#include <gtest/gtest.h>

#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/stencil.hpp"
#include "framebuffer/stencil_picture.hpp"

namespace mpr {
namespace {

const std::uint32_t kStored[] = {0, 1, 2, 127, 128, 129, 192, 254, 255};
const std::uint32_t kMasks[] = {0xFF, 0x00, 0x0F, 0xF0, 0x01, 0x80, 0x7F};

// The GL 1.1 text, written out per function: "(ref & mask) OP (stored & mask)".
bool glSpecPasses(CompareFunc f, std::uint32_t ref, std::uint32_t stored, std::uint32_t mask) {
  const std::uint32_t r = ref & mask, s = stored & mask;
  if (f == CompareFunc::Never) return false;
  if (f == CompareFunc::Always) return true;
  if (f == CompareFunc::Less) return r < s;
  if (f == CompareFunc::Lequal) return r <= s;
  if (f == CompareFunc::Greater) return r > s;
  if (f == CompareFunc::Gequal) return r >= s;
  if (f == CompareFunc::Equal) return r == s;
  return r != s;  // Notequal
}

TEST(StencilTest, EveryFunctionReferenceAndValueMask) {
  const CompareFunc funcs[] = {CompareFunc::Never, CompareFunc::Less, CompareFunc::Equal, CompareFunc::Lequal,
                               CompareFunc::Greater, CompareFunc::Notequal, CompareFunc::Gequal, CompareFunc::Always};
  int checked = 0;
  for (CompareFunc f : funcs)
    for (std::uint32_t ref : kStored)
      for (std::uint32_t stored : kStored)
        for (std::uint32_t mask : kMasks) {
          StencilState s;
          s.func = f;
          s.ref = ref;
          s.valueMask = mask;
          ASSERT_EQ(stencilTest(s, stored), glSpecPasses(f, ref, stored, mask))
              << "func " << int(f) << " ref " << ref << " stored " << stored << " mask " << mask;
          ++checked;
        }
  EXPECT_EQ(checked, 8 * 9 * 9 * 7);
}

TEST(StencilTest, ReferenceIsOnTheLeft) {
  // The paper's "GREATER, SHAD_MIN" means stored values greater than SHAD_MIN;
  // GL_GREATER with ref 128 passes when 128 > stored, i.e. stored < 128.
  StencilState s;
  s.func = CompareFunc::Greater;
  s.ref = 128;
  EXPECT_TRUE(stencilTest(s, 127));
  EXPECT_FALSE(stencilTest(s, 128));
  EXPECT_FALSE(stencilTest(s, 200));
  s.func = CompareFunc::Less;  // passes when 128 < stored
  EXPECT_TRUE(stencilTest(s, 129));
  EXPECT_FALSE(stencilTest(s, 128));
}

struct OpCase {
  StencilOp op;
  std::uint32_t stored, ref, expected;  // write mask 0xFF
};

TEST(StencilOps, ValuesAtTheEdgesOfTheRange) {
  const OpCase cases[] = {
      {StencilOp::Keep, 77, 5, 77},       {StencilOp::Zero, 77, 5, 0},
      {StencilOp::Replace, 77, 5, 5},     {StencilOp::Replace, 0, 255, 255},
      {StencilOp::Incr, 0, 0, 1},         {StencilOp::Incr, 254, 0, 255},
      {StencilOp::Incr, 255, 0, 255},     // saturates
      {StencilOp::Decr, 1, 0, 0},         {StencilOp::Decr, 0, 0, 0},  // saturates
      {StencilOp::Decr, 255, 0, 254},     {StencilOp::Invert, 0, 0, 255},
      {StencilOp::Invert, 0x5A, 0, 0xA5}, {StencilOp::IncrWrap, 255, 0, 0},  // wraps
      {StencilOp::IncrWrap, 127, 0, 128}, {StencilOp::DecrWrap, 0, 0, 255},  // wraps
      {StencilOp::DecrWrap, 128, 0, 127},
  };
  for (const OpCase& c : cases) {
    StencilState s;
    s.ref = c.ref;
    EXPECT_EQ(applyStencilOp(c.op, c.stored, s, 255), c.expected) << "op " << int(c.op) << " on " << c.stored;
  }
}

TEST(StencilOps, WriteMaskKeepsUnmaskedBits) {
  // (stored & ~mask) | (new & mask), hand-evaluated.
  StencilState s;
  s.ref = 0xFF;
  s.writeMask = 0x0F;
  EXPECT_EQ(applyStencilOp(StencilOp::Replace, 0xA0, s, 255), 0xAFu);
  EXPECT_EQ(applyStencilOp(StencilOp::Zero, 0xAB, s, 255), 0xA0u);
  EXPECT_EQ(applyStencilOp(StencilOp::Invert, 0xAB, s, 255), 0xA4u);
  EXPECT_EQ(applyStencilOp(StencilOp::Incr, 0x0F, s, 255), 0x00u);  // 0x10 masked to its low nibble
  s.writeMask = 0xF0;
  EXPECT_EQ(applyStencilOp(StencilOp::Incr, 0x0F, s, 255), 0x1Fu);
  EXPECT_EQ(applyStencilOp(StencilOp::Decr, 0x10, s, 255), 0x00u);  // 0x0F: its high nibble 0 replaces 1; low nibble kept (0)
  s.writeMask = 0x00;
  for (StencilOp op : {StencilOp::Zero, StencilOp::Replace, StencilOp::Incr, StencilOp::Decr, StencilOp::Invert,
                       StencilOp::IncrWrap, StencilOp::DecrWrap})
    EXPECT_EQ(applyStencilOp(op, 0x3C, s, 255), 0x3Cu);
  s.writeMask = 0x80;  // a single bit
  EXPECT_EQ(applyStencilOp(StencilOp::Replace, 0x00, s, 255), 0x80u);
  EXPECT_EQ(applyStencilOp(StencilOp::IncrWrap, 0x7F, s, 255), 0xFFu);  // bit 7 from 0x80, the rest kept
  EXPECT_EQ(applyStencilOp(StencilOp::IncrWrap, 0x7E, s, 255), 0x7Eu);
}

TEST(StencilOps, EveryOpTimesWriteMaskFamily) {
  // Against the definition per bit: unmasked bits keep the stored value.
  for (StencilOp op : {StencilOp::Keep, StencilOp::Zero, StencilOp::Replace, StencilOp::Incr, StencilOp::Decr,
                       StencilOp::Invert, StencilOp::IncrWrap, StencilOp::DecrWrap})
    for (std::uint32_t mask : kMasks)
      for (std::uint32_t stored : kStored) {
        StencilState s;
        s.ref = 0x5A;
        s.writeMask = mask;
        const std::uint32_t full = stencilOpValue(op, stored, s.ref, 255);
        const std::uint32_t got = applyStencilOp(op, stored, s, 255);
        for (int bit = 0; bit < 8; ++bit) {
          const std::uint32_t b = 1u << bit;
          ASSERT_EQ(got & b, (mask & b) ? (full & b) : (stored & b)) << "op " << int(op) << " mask " << mask;
        }
      }
}

TEST(StencilOps, NarrowProfileSaturatesAtItsWidth) {
  // A 4-bit stencil: INCR saturates at 15, INVERT flips four bits, masks are
  // taken modulo the width.
  StencilState s;
  EXPECT_EQ(applyStencilOp(StencilOp::Incr, 15, s, 15), 15u);
  EXPECT_EQ(applyStencilOp(StencilOp::IncrWrap, 15, s, 15), 0u);
  EXPECT_EQ(applyStencilOp(StencilOp::DecrWrap, 0, s, 15), 15u);
  EXPECT_EQ(applyStencilOp(StencilOp::Invert, 0x5, s, 15), 0xAu);
  s.ref = 0xFF;  // callers clamp; Replace keeps only the width
  EXPECT_EQ(applyStencilOp(StencilOp::Replace, 0, s, 15), 15u);
}

// Through processFragment: which of the three operations applies.
struct Rig {
  Framebuffer fb{4, 1, indigoProfile()};
  FragmentState st;
  Rig() {
    st.stencil.enabled = true;
    st.stencil.sfail = StencilOp::Replace;   // ref 10
    st.stencil.dpfail = StencilOp::Incr;
    st.stencil.dppass = StencilOp::Invert;
    st.stencil.ref = 10;
    st.depth.func = CompareFunc::Less;
  }
  std::uint32_t run(std::uint8_t stored, bool stencilPasses, bool depthEnabled, bool depthPasses) {
    fb.stencil(0, 0) = stored;
    fb.depth(0, 0) = 100;
    st.stencil.func = stencilPasses ? CompareFunc::Always : CompareFunc::Never;
    st.depth.enabled = depthEnabled;
    processFragment(st, fb, Fragment{0, 0, depthPasses ? 50u : 150u, Rgba8{1, 2, 3, 4}, 1.0f});
    return fb.stencil(0, 0);
  }
};

TEST(StencilOps, SfailDpfailDppassSelection) {
  Rig r;
  EXPECT_EQ(r.run(3, false, true, true), 10u);      // stencil fails: sfail (REPLACE 10)
  EXPECT_EQ(r.run(3, true, true, false), 4u);       // depth fails: dpfail (INCR)
  EXPECT_EQ(r.run(3, true, true, true), 252u);      // both pass: dppass (INVERT 3)
  EXPECT_EQ(r.run(3, true, false, false), 252u);    // depth test off: dppass
  r.st.stencil.enabled = false;
  EXPECT_EQ(r.run(3, true, true, false), 3u);       // stencil test off: untouched
}

TEST(StencilPicture, ReportsMismatchesWithBothValues) {
  Framebuffer fb(3, 2, indigoProfile());
  fb.stencil(0, 1) = 1;
  fb.stencil(2, 0) = 200;
  EXPECT_EQ(stencilPictureMismatch(fb, 0, 0, R"(
      1 . .
      . . 200)"), "");
  EXPECT_EQ(stencilPictureMismatch(fb, 0, 0, "* * *\n* * 200"), "");
  const std::string report = stencilPictureMismatch(fb, 0, 0, "1 . .\n. 5 200");
  EXPECT_NE(report.find("(1,0): expected 5, stored 0"), std::string::npos) << report;
  EXPECT_NE(stencilPictureMismatch(fb, 0, 0, "1 .\n. . ."), "");     // ragged
  EXPECT_NE(stencilPictureMismatch(fb, 1, 1, ". .\n. ."), "");        // outside the window
  EXPECT_EQ(stencilPicture(fb, fb.bounds()), "   1   .   .\n   .   . 200\n");
}

}  // namespace
}  // namespace mpr
