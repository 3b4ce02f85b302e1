// Which stencil operation a fragment takes, per pixel: sfail when the
// stencil test fails, dpfail when it passes and the depth test fails, dppass
// when both pass or the depth test is disabled; none with the stencil test
// disabled; the write mask on every slot (GL 1.1 section 4.1.4).
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
namespace mpr::stencil_selection_per_pixel_test {
namespace {

using test::stencilMatches;

using stencil_per_pixel::frag;
using stencil_per_pixel::setRow;

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

}  // namespace
}  // namespace mpr::stencil_selection_per_pixel_test
