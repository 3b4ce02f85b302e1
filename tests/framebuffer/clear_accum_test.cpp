// Clears under scissor and masks, and the accumulation buffer's words after
// every operation for both profiles.
#include <gtest/gtest.h>

#include "framebuffer/accumulation.hpp"
#include "framebuffer/clear.hpp"
#include "framebuffer/stencil_picture.hpp"

namespace mpr {
namespace {

TEST(Clear, ScissorAndMasks) {
  Framebuffer fb(4, 3, indigoProfile());
  ClearValues v;
  v.color = {10, 20, 30, 40};
  v.depth = 0xABCDEF;
  v.stencil = 0xFF;
  v.accum = {1, 2, 3, 4};
  clearBuffers(fb, fb.bounds(), {true, true, true, true}, v, ClearMasks{});
  EXPECT_EQ(fb.color(3, 2), (Rgba8{10, 20, 30, 40}));
  EXPECT_EQ(fb.depth(0, 0), 0xABCDEFu);
  EXPECT_EQ(fb.accum(1, 1)[2], 3);
  EXPECT_EQ(fb.accum(1, 1)[3], 0);  // indigo has no alpha word

  ClearValues w;
  w.color = {0, 0, 0, 0};
  w.stencil = 0x00;
  w.depth = 0;
  ClearMasks m;
  m.color = {false, true, false, true};
  m.stencil = 0x0F;
  m.depth = false;
  clearBuffers(fb, PixelRect{1, 1, 3, 3}, {true, true, true, true}, w, m);  // pixels x 1..2, y 1..2
  EXPECT_EQ(stencilPictureMismatch(fb, 0, 0, R"(
      255 240 240 255
      255 240 240 255
      255 255 255 255)"), "");
  EXPECT_EQ(fb.color(1, 1), (Rgba8{10, 0, 30, 0}));
  EXPECT_EQ(fb.color(0, 1), (Rgba8{10, 20, 30, 40}));
  EXPECT_EQ(fb.depth(1, 1), 0xABCDEFu);   // depth mask off
  EXPECT_EQ(fb.accum(1, 1)[0], 0);        // accumulation ignores masks
  EXPECT_EQ(fb.accum(0, 1)[0], 1);        // but not the scissor
}

TEST(Accumulation, ClearWordsFollowMesa) {
  // ((int)(65535 * v) - 1) / 2 with C division.
  EXPECT_EQ(accumClearWord(1.0f), 32767);
  EXPECT_EQ(accumClearWord(0.0f), 0);     // (0 - 1) / 2 = 0
  EXPECT_EQ(accumClearWord(-1.0f), -32768);
  EXPECT_EQ(accumClearWord(0.5f), 16383); // (32767 - 1) / 2
  EXPECT_EQ(accumClearWord(-0.5f), -16384); // (-32767 - 1) / 2
}

struct AccumRig {
  Framebuffer fb;
  explicit AccumRig(const HardwareProfile& p) : fb(2, 1, p) {}
  const std::int16_t* word(int x = 0) { return fb.accum(x, 0); }
  void run(AccumOp op, float v) { accumulate(fb, fb.bounds(), op, v, {true, true, true, true}); }
};

TEST(Accumulation, LoadAccumReturnMesa) {
  AccumRig r(mesaProfile());
  r.fb.color(0, 0) = {255, 128, 0, 51};
  r.run(AccumOp::Load, 1.0f);
  // byte * (1/255) * 32767, truncated: 32767, 128/255*32767 = 16447.6 -> 16447, 0, 51/255*32767 = 6553.4 -> 6553
  EXPECT_EQ(r.word()[0], 32767);
  EXPECT_EQ(r.word()[1], 16447);
  EXPECT_EQ(r.word()[2], 0);
  EXPECT_EQ(r.word()[3], 6553);
  r.run(AccumOp::Accum, -0.5f);
  // adds trunc(-16383.5) = -16383, trunc(-8223.8) = -8223, 0, trunc(-3276.7) = -3276
  EXPECT_EQ(r.word()[0], 16384);
  EXPECT_EQ(r.word()[1], 8224);
  EXPECT_EQ(r.word()[3], 3277);
  r.run(AccumOp::Return, 2.0f);
  // 16384 * 2/32767 = 1.00003 -> 255; 8224 * 2/32767 = 0.50197 -> 128.0 -> 128; 3277 * 2 / 32767 = 0.20002 -> 51.005 -> 51
  EXPECT_EQ(r.fb.color(0, 0), (Rgba8{255, 128, 0, 51}));
}

TEST(Accumulation, MultAndAddTruncate) {
  AccumRig r(mesaProfile());
  r.fb.color(0, 0) = {255, 255, 255, 255};
  r.run(AccumOp::Load, 1.0f);  // 32767 everywhere
  r.run(AccumOp::Mult, 0.3f);  // 32767 * 0.3 = 9830.1 -> 9830
  EXPECT_EQ(r.word()[0], 9830);
  r.run(AccumOp::Add, -0.1f);  // trunc(-0.1 * 32767) = trunc(-3276.7) = -3276
  EXPECT_EQ(r.word()[0], 6554);
  EXPECT_EQ(r.word()[3], 6554);  // ADD and MULT touch all four words on mesa
}

TEST(Accumulation, OverflowWrapsOnMesaAndSaturatesOnIndigo) {
  AccumRig mesa(mesaProfile()), indigo(indigoProfile());
  for (AccumRig* r : {&mesa, &indigo}) {
    r->fb.color(0, 0) = {255, 255, 255, 255};
    r->run(AccumOp::Load, 1.0f);   // 32767
    r->run(AccumOp::Accum, 1.0f);  // + 32767
  }
  EXPECT_EQ(mesa.word()[0], -2);  // 65534 - 65536
  EXPECT_EQ(indigo.word()[0], 32767);
  for (AccumRig* r : {&mesa, &indigo}) r->run(AccumOp::Add, -1.0f);  // -32767
  EXPECT_EQ(mesa.word()[0], 32767);   // -2 - 32767 = -32769 wraps to 32767
  EXPECT_EQ(indigo.word()[0], 0);
  EXPECT_EQ(indigo.word()[3], 0);     // no alpha word on indigo
  for (AccumRig* r : {&mesa, &indigo}) r->run(AccumOp::Mult, -1.5f);
  EXPECT_EQ(mesa.word()[0], 16386);   // 32767 * -1.5 = -49150.5 -> -49150, + 65536
  EXPECT_EQ(indigo.word()[0], 0);
  indigo.run(AccumOp::Load, 1.0f);      // 32767 again
  indigo.run(AccumOp::Mult, -1.5f);
  EXPECT_EQ(indigo.word()[0], -32768);  // -49150 clamps
}

TEST(Accumulation, ReturnHonoursScissorAndColourMaskAndKeepsIndigoAlpha) {
  AccumRig r(indigoProfile());
  r.fb.color(0, 0) = r.fb.color(1, 0) = {255, 255, 255, 255};
  r.run(AccumOp::Load, 0.5f);  // 16383 on RGB, alpha word stays 0
  EXPECT_EQ(r.word()[0], 16383);
  EXPECT_EQ(r.word()[3], 0);
  r.fb.color(0, 0) = r.fb.color(1, 0) = {0, 0, 0, 77};
  accumulate(r.fb, PixelRect{1, 0, 2, 1}, AccumOp::Return, 1.0f, {true, false, true, true});
  EXPECT_EQ(r.fb.color(0, 0), (Rgba8{0, 0, 0, 77}));   // outside the region
  // 16383 / 32767 * 255 = 127.496 -> 127; green masked; alpha has no word: kept
  EXPECT_EQ(r.fb.color(1, 0), (Rgba8{127, 0, 127, 77}));
}

}  // namespace
}  // namespace mpr
