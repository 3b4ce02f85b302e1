// The accumulation buffer word by word, for both profiles: every glAccum
// operation, overflow (wrapping on mesa, saturating on indigo), the region
// (scissor) restriction, the colour mask on GL_RETURN, indigo's missing alpha
// word, and the glClearAccum words.
//
// Every expected value is derived by hand in the comment beside it, in the
// float arithmetic Mesa's main/accum.c uses:
//   byte -> unit     b * fl(1/255)        (fl(1/255) = 0.0039215689, a hair above 1/255)
//   LOAD / ACCUM     (short)(unit * fl(value * 32767))
//   MULT             (short)(word * value)
//   ADD              word + (short)(value * 32767)
//   RETURN           round_half_even(clamp(word * fl(value / 32767), 0, 1) * 255)
//   glClearAccum     ((int)(65535 * v) - 1) / 2, C division
// where (short)(float) is x86-64's: truncate toward zero into 32 bits (0x80000000
// when out of range or NaN), keep the low 16 bits. The mesa numbers were checked
// against OSMesa 22.3 (llvmpipe and softpipe): their words, decoded through
// GL_RETURN, are these.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "framebuffer/accumulation.hpp"
#include "framebuffer/clear.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"

namespace mpr {
namespace {

using Words = std::array<std::int16_t, 4>;
constexpr std::array<bool, 4> kAllChannels{true, true, true, true};

Words wordsAt(const Framebuffer& fb, int x, int y) {
  const std::int16_t* a = fb.accum(x, y);
  return {a[0], a[1], a[2], a[3]};
}

void setWords(Framebuffer& fb, int x, int y, const Words& w) {
  for (int c = 0; c < 4; ++c) fb.accum(x, y)[c] = w[c];
}

void fillColor(Framebuffer& fb, const Rgba8& c) {
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) fb.color(x, y) = c;
}

void everywhere(Framebuffer& fb, AccumOp op, float value) {
  accumulate(fb, fb.bounds(), op, value, kAllChannels);
}

// ---- mesa: products truncate toward zero, sums wrap ---------------------------

TEST(AccumMesa, LoadTruncatesEveryProductTowardZero) {
  Framebuffer fb(3, 1, mesaProfile());
  fb.color(0, 0) = {255, 128, 1, 254};
  fb.color(1, 0) = {3, 51, 37, 0};
  fb.color(2, 0) = {255, 128, 1, 254};
  accumulate(fb, PixelRect{0, 0, 2, 1}, AccumOp::Load, 1.0f, kAllChannels);
  // scale = 32767.
  // 255 * fl(1/255) rounds to exactly 1.0 -> 32767
  // 128 * fl(1/255) = 0.50196081; * 32767 = 16447.75 in float -> 16447 (rounding would give 16448)
  //   1 -> 0.0039215689 * 32767 = 128.498 -> 128
  // 254 -> 0.99607849 * 32767 = 32638.504 -> 32638 (rounding would give 32639)
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 16447, 128, 32638}));
  //   3 -> 385.494 -> 385;  51 -> 6553.400 -> 6553;  37 -> 4754.428 -> 4754;  0 -> 0
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{385, 6553, 4754, 0}));

  accumulate(fb, PixelRect{2, 0, 3, 1}, AccumOp::Load, -1.0f, kAllChannels);
  // scale = -32767: the same magnitudes, truncated toward zero (not floored):
  // -32767, -16447.75 -> -16447, -128.498 -> -128, -32638.504 -> -32638
  EXPECT_EQ(wordsAt(fb, 2, 0), (Words{-32767, -16447, -128, -32638}));
}

TEST(AccumMesa, LoadReplacesTheOldWords) {
  Framebuffer fb(1, 1, mesaProfile());
  setWords(fb, 0, 0, {-7, 1234, -32768, 32767});
  fb.color(0, 0) = {0, 0, 0, 0};
  everywhere(fb, AccumOp::Load, 0.5f);
  // 0 * anything = 0; LOAD does not add
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{0, 0, 0, 0}));
}

TEST(AccumMesa, LoadOverflowWrapsModulo65536) {
  Framebuffer fb(1, 1, mesaProfile());
  fb.color(0, 0) = {255, 128, 37, 1};
  everywhere(fb, AccumOp::Load, 2.0f);
  // scale = 65534.
  // 255: 1.0 * 65534 = 65534 -> low 16 bits as a short: 65534 - 65536 = -2
  // 128: 0.50196081 * 65534 = 32895.5 -> 32895 -> 32895 - 65536 = -32641
  //  37: 0.14509805 * 65534 = 9508.855 -> 9508 (in range)
  //   1: 0.0039215689 * 65534 = 256.996 -> 256
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{-2, -32641, 9508, 256}));
}

TEST(AccumMesa, AccumAddsTruncatedProductsAndWraps) {
  Framebuffer fb(1, 1, mesaProfile());
  fb.color(0, 0) = {255, 254, 128, 0};
  everywhere(fb, AccumOp::Load, 1.0f);
  // as in LoadTruncatesEveryProductTowardZero: 32767, 32638, 16447, 0
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 32638, 16447, 0}));
  everywhere(fb, AccumOp::Accum, 1.0f);
  // doubled and wrapped: 65534 - 65536 = -2, 65276 - 65536 = -260, 32894 - 65536 = -32642, 0
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{-2, -260, -32642, 0}));
}

TEST(AccumMesa, AccumOfANegativeValueTruncatesTowardZero) {
  Framebuffer fb(1, 1, mesaProfile());
  fb.color(0, 0) = {255, 129, 77, 3};
  everywhere(fb, AccumOp::Accum, -0.3f);
  // scale = fl(-0.3f * 32767) = -9830.1006; words start at 0.
  // 255: 1.0 * -9830.1006 -> -9830
  // 129: 0.50588238 * -9830.1006 = -4972.875 -> -4972 (floor would be -4973)
  //  77: 0.30196080 * -9830.1006 = -2968.305 -> -2968
  //   3: 0.011764707 * -9830.1006 = -115.648 -> -115
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{-9830, -4972, -2968, -115}));
}

TEST(AccumMesa, RepeatedAccumLosesTheTruncatedFractions) {
  Framebuffer fb(1, 1, mesaProfile());
  fb.color(0, 0) = {255, 129, 77, 3};
  for (int i = 0; i < 4; ++i) everywhere(fb, AccumOp::Accum, 0.25f);
  // scale = 0.25 * 32767 = 8191.75 each time:
  // 255: 8191.75 -> 8191, x4 = 32764 (not 32767)
  // 129: 0.50588238 * 8191.75 = 4144.06 -> 4144, x4 = 16576
  //  77: 0.30196080 * 8191.75 = 2473.59 -> 2473, x4 = 9892
  //   3: 0.011764707 * 8191.75 = 96.37 -> 96, x4 = 384
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32764, 16576, 9892, 384}));
}

TEST(AccumMesa, MultTruncatesAndWraps) {
  const Words loaded{32767, 16447, 4754, 128};  // LOAD 1.0 of (255, 128, 37, 1), derived above
  Framebuffer fb(4, 1, mesaProfile());
  for (int x = 0; x < 4; ++x) setWords(fb, x, 0, loaded);
  accumulate(fb, PixelRect{0, 0, 1, 1}, AccumOp::Mult, 0.3f, kAllChannels);
  // 32767 * 0.3f = 9830.10 -> 9830; 16447 * 0.3 = 4934.10 -> 4934; 4754 * 0.3 = 1426.20 -> 1426;
  // 128 * 0.3 = 38.40 -> 38
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{9830, 4934, 1426, 38}));
  accumulate(fb, PixelRect{1, 0, 2, 1}, AccumOp::Mult, -1.5f, kAllChannels);
  // 32767 * -1.5 = -49150.5 -> -49150 -> + 65536 = 16386; 16447 * -1.5 = -24670.5 -> -24670;
  // 4754 * -1.5 = -7131; 128 * -1.5 = -192
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{16386, -24670, -7131, -192}));
  accumulate(fb, PixelRect{2, 0, 3, 1}, AccumOp::Mult, 2.0f, kAllChannels);
  // 65534 -> -2; 32894 -> -32642; 9508; 256
  EXPECT_EQ(wordsAt(fb, 2, 0), (Words{-2, -32642, 9508, 256}));
  accumulate(fb, PixelRect{3, 0, 4, 1}, AccumOp::Mult, 1e6f, kAllChannels);
  // 32767e6, 16447e6 and 4754e6 do not fit 32 bits: 0x80000000, whose low 16 bits are 0.
  // 128e6 = 128000000 fits: 128000000 - 1953 * 65536 = 8192
  EXPECT_EQ(wordsAt(fb, 3, 0), (Words{0, 0, 0, 8192}));
}

TEST(AccumMesa, AddTruncatesTheIncrementAndWraps) {
  const Words loaded{32767, 16447, 4754, 128};
  Framebuffer fb(4, 1, mesaProfile());
  for (int x = 0; x < 4; ++x) setWords(fb, x, 0, loaded);
  accumulate(fb, PixelRect{0, 0, 1, 1}, AccumOp::Add, 0.1f, kAllChannels);
  // increment = (short)(0.1f * 32767 = 3276.70) = 3276
  // 32767 + 3276 = 36043 -> 36043 - 65536 = -29493; 19723; 8030; 3404
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{-29493, 19723, 8030, 3404}));
  accumulate(fb, PixelRect{1, 0, 2, 1}, AccumOp::Add, -0.1f, kAllChannels);
  // increment = -3276 (toward zero, not -3277): 29491, 13171, 1478, -3148
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{29491, 13171, 1478, -3148}));
  accumulate(fb, PixelRect{2, 0, 3, 1}, AccumOp::Add, 2.0f, kAllChannels);
  // increment = (short)65534 = -2: 32765, 16445, 4752, 126
  EXPECT_EQ(wordsAt(fb, 2, 0), (Words{32765, 16445, 4752, 126}));
  accumulate(fb, PixelRect{3, 0, 4, 1}, AccumOp::Add, 1e6f, kAllChannels);
  // 1e6 * 32767 does not fit 32 bits: 0x80000000 -> increment 0, nothing changes
  EXPECT_EQ(wordsAt(fb, 3, 0), loaded);
}

TEST(AccumMesa, NonFiniteValuesGiveZeroProducts) {
  Framebuffer fb(4, 1, mesaProfile());
  fillColor(fb, {255, 128, 0, 1});
  for (int x = 0; x < 4; ++x) setWords(fb, x, 0, {32767, 16447, 0, 128});
  accumulate(fb, PixelRect{0, 0, 1, 1}, AccumOp::Load, NAN, kAllChannels);
  // NaN -> 0x80000000 -> 0
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{0, 0, 0, 0}));
  accumulate(fb, PixelRect{1, 0, 2, 1}, AccumOp::Mult, INFINITY, kAllChannels);
  // w * inf is inf (or NaN for w = 0) -> 0x80000000 -> 0
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{0, 0, 0, 0}));
  accumulate(fb, PixelRect{2, 0, 3, 1}, AccumOp::Add, -INFINITY, kAllChannels);
  // increment (short)(-inf) = 0: unchanged
  EXPECT_EQ(wordsAt(fb, 2, 0), (Words{32767, 16447, 0, 128}));
  accumulate(fb, PixelRect{3, 0, 4, 1}, AccumOp::Accum, INFINITY, kAllChannels);
  // every product inf or NaN -> 0 added: unchanged
  EXPECT_EQ(wordsAt(fb, 3, 0), (Words{32767, 16447, 0, 128}));
}

TEST(AccumMesa, ReturnRoundsHalfToEvenAndClamps) {
  Framebuffer fb(6, 1, mesaProfile());
  setWords(fb, 0, 0, {32767, 16383, 16384, -5});
  setWords(fb, 1, 0, {192, 193, 1000, -32768});
  accumulate(fb, PixelRect{0, 0, 2, 1}, AccumOp::Return, 1.0f, kAllChannels);
  // scale = fl(1/32767); byte = w * scale * 255:
  // 32767 -> 255.0 -> 255; 16383 -> 127.496 -> 127; 16384 -> 127.504 -> 128; -5 -> negative -> 0
  EXPECT_EQ(fb.color(0, 0), (Rgba8{255, 127, 128, 0}));
  // 192 -> 1.494 -> 1; 193 -> 1.502 -> 2; 1000 -> 7.782 -> 8; -32768 -> 0
  EXPECT_EQ(fb.color(1, 0), (Rgba8{1, 2, 8, 0}));

  setWords(fb, 2, 0, {16384, 8224, 32767, 0});
  accumulate(fb, PixelRect{2, 0, 3, 1}, AccumOp::Return, 2.0f, kAllChannels);
  // 16384 * 2 / 32767 = 1.00003 -> clamped to 1 -> 255; 8224 -> 128.002 -> 128;
  // 32767 -> 2.0 -> 255; 0 -> 0
  EXPECT_EQ(fb.color(2, 0), (Rgba8{255, 128, 255, 0}));

  // Exact halves. Each value v below was searched for so that, in float,
  // (32767 * fl(v / 32767)) * 255 is exactly k + 0.5; OSMesa writes the even byte.
  setWords(fb, 3, 0, {32767, 32767, 32767, 32767});
  setWords(fb, 4, 0, {32767, 32767, 32767, 32767});
  setWords(fb, 5, 0, {32767, 32767, 32767, 32767});
  accumulate(fb, PixelRect{3, 0, 4, 1}, AccumOp::Return, 0.00980392192f, kAllChannels);
  EXPECT_EQ(fb.color(3, 0), (Rgba8{2, 2, 2, 2}));  // 2.5 -> 2 (half up would give 3)
  accumulate(fb, PixelRect{4, 0, 5, 1}, AccumOp::Return, 0.0176470596f, kAllChannels);
  EXPECT_EQ(fb.color(4, 0), (Rgba8{4, 4, 4, 4}));  // 4.5 -> 4
  accumulate(fb, PixelRect{5, 0, 6, 1}, AccumOp::Return, 0.00588235306f, kAllChannels);
  EXPECT_EQ(fb.color(5, 0), (Rgba8{2, 2, 2, 2}));  // 1.5 -> 2
}

TEST(AccumMesa, ReturnLeavesTheWordsAlone) {
  Framebuffer fb(1, 1, mesaProfile());
  setWords(fb, 0, 0, {100, -100, 32767, 5});
  everywhere(fb, AccumOp::Return, 3.0f);
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{100, -100, 32767, 5}));
  // 100 * 3 / 32767 * 255 = 2.335 -> 2; -100 -> 0; 32767 * 3 -> 3.0 -> 255; 5 -> 0.117 -> 0
  EXPECT_EQ(fb.color(0, 0), (Rgba8{2, 0, 255, 0}));
}

// ---- indigo: RGB words only, sums and products saturate -----------------------

TEST(AccumIndigo, LoadLeavesTheAlphaWordZero) {
  Framebuffer fb(1, 1, indigoProfile());
  fb.color(0, 0) = {255, 128, 1, 255};
  everywhere(fb, AccumOp::Load, 1.0f);
  // RGB as on mesa (32767, 16447.75 -> 16447, 128.498 -> 128); no alpha word
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 16447, 128, 0}));
  everywhere(fb, AccumOp::Accum, -0.25f);
  // scale -8191.75: 255 -> -8191, 128 -> 0.50196081 * -8191.75 = -4111.94 -> -4111,
  // 1 -> -32.12 -> -32; sums 24576, 12336, 96; alpha still 0
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{24576, 12336, 96, 0}));
  everywhere(fb, AccumOp::Add, 0.5f);
  // increment 16383.5 -> 16383; 24576 + 16383 = 40959 -> saturates at 32767;
  // 12336 + 16383 = 28719; 96 + 16383 = 16479; ADD does not touch the missing alpha word
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 28719, 16479, 0}));
  everywhere(fb, AccumOp::Mult, 0.5f);
  // 16383.5 -> 16383; 14359.5 -> 14359; 8239.5 -> 8239; alpha 0 * 0.5 stays 0
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{16383, 14359, 8239, 0}));
}

TEST(AccumIndigo, SumsSaturate) {
  Framebuffer fb(1, 1, indigoProfile());
  fb.color(0, 0) = {255, 254, 128, 0};
  everywhere(fb, AccumOp::Load, 1.0f);  // 32767, 32638, 16447
  everywhere(fb, AccumOp::Accum, 1.0f);
  // 65534 -> 32767; 65276 -> 32767; 32894 -> 32767 (mesa wraps these to -2, -260, -32642)
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 32767, 32767, 0}));
  everywhere(fb, AccumOp::Add, 1.0f);  // + 32767, still 32767
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 32767, 32767, 0}));
  everywhere(fb, AccumOp::Add, -1.0f);  // 32767 - 32767 = 0
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{0, 0, 0, 0}));
  everywhere(fb, AccumOp::Add, -1.0f);  // -32767
  everywhere(fb, AccumOp::Add, -1.0f);  // -65534 -> -32768
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{-32768, -32768, -32768, 0}));
  everywhere(fb, AccumOp::Accum, -1.0f);  // -32768 - 32767, - 32638, - 16447: all -32768
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{-32768, -32768, -32768, 0}));
}

TEST(AccumIndigo, ProductsSaturate) {
  Framebuffer fb(5, 1, indigoProfile());
  fillColor(fb, {255, 128, 64, 255});
  accumulate(fb, PixelRect{0, 0, 1, 1}, AccumOp::Load, 2.0f, kAllChannels);
  // 65534 -> 32767; 32895.5 -> 32895 -> 32767; 64: 0.25098041 * 65534 = 16447.75 -> 16447
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 32767, 16447, 0}));
  accumulate(fb, PixelRect{1, 0, 2, 1}, AccumOp::Load, -2.0f, kAllChannels);
  // -65534 -> -32768; -32895 -> -32768; -16447
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{-32768, -32768, -16447, 0}));

  setWords(fb, 2, 0, {32767, 16447, 128, 0});
  accumulate(fb, PixelRect{2, 0, 3, 1}, AccumOp::Mult, -1.5f, kAllChannels);
  // -49150.5 -> -49150 -> -32768; -24670.5 -> -24670; -192
  EXPECT_EQ(wordsAt(fb, 2, 0), (Words{-32768, -24670, -192, 0}));
  setWords(fb, 3, 0, {32767, 16447, 128, 0});
  accumulate(fb, PixelRect{3, 0, 4, 1}, AccumOp::Mult, 1e6f, kAllChannels);
  // all three far above 32767 -> 32767 (mesa gives 0, 0, 8192)
  EXPECT_EQ(wordsAt(fb, 3, 0), (Words{32767, 32767, 32767, 0}));
  setWords(fb, 4, 0, {1, -1, 0, 0});
  accumulate(fb, PixelRect{4, 0, 5, 1}, AccumOp::Add, 2.0f, kAllChannels);
  // increment 65534 saturates to 32767 (mesa: -2); 1 + 32767 -> 32767; -1 + 32767 = 32766; 32767
  EXPECT_EQ(wordsAt(fb, 4, 0), (Words{32767, 32766, 32767, 0}));
}

TEST(AccumIndigo, NaNProductsAreZero) {
  Framebuffer fb(2, 1, indigoProfile());
  fillColor(fb, {255, 255, 255, 255});
  setWords(fb, 0, 0, {5, 6, 7, 0});
  setWords(fb, 1, 0, {5, 6, 7, 0});
  accumulate(fb, PixelRect{0, 0, 1, 1}, AccumOp::Load, NAN, kAllChannels);
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{0, 0, 0, 0}));
  accumulate(fb, PixelRect{1, 0, 2, 1}, AccumOp::Mult, NAN, kAllChannels);
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{0, 0, 0, 0}));
}

TEST(AccumIndigo, ReturnKeepsDestinationAlpha) {
  Framebuffer fb(1, 1, indigoProfile());
  fb.color(0, 0) = {9, 9, 9, 77};
  setWords(fb, 0, 0, {16383, 32767, -1, 0});
  everywhere(fb, AccumOp::Return, 1.0f);
  // 127.496 -> 127; 255; negative -> 0; no alpha word: the destination alpha 77 stays
  // although the colour mask enables alpha
  EXPECT_EQ(fb.color(0, 0), (Rgba8{127, 255, 0, 77}));
}

// ---- both: region, colour mask, clear words -----------------------------------

// Each operation on the two pixels of region {1,0}-{3,1} of a 3x2 window whose
// colour is white and whose words are all 1000 (indigo: alpha word 0).
class AccumRegion : public ::testing::TestWithParam<bool> {
 protected:
  const HardwareProfile& profile() const { return GetParam() ? mesaProfile() : indigoProfile(); }
  std::int16_t alphaWord(std::int16_t v) const { return GetParam() ? v : 0; }
  Framebuffer fresh() const {
    Framebuffer fb(3, 2, profile());
    fillColor(fb, {255, 255, 255, 255});
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) setWords(fb, x, y, {1000, 1000, 1000, alphaWord(1000)});
    return fb;
  }
  // Pixels outside the region still hold the untouched words and colour.
  void expectOutsideUntouched(const Framebuffer& fb) const {
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) {
        if (y == 0 && x >= 1) continue;
        SCOPED_TRACE(::testing::Message() << "pixel " << x << "," << y);
        EXPECT_EQ(wordsAt(fb, x, y), (Words{1000, 1000, 1000, alphaWord(1000)}));
        EXPECT_EQ(fb.color(x, y), (Rgba8{255, 255, 255, 255}));
      }
  }
  void expectInside(const Framebuffer& fb, const Words& w) const {
    EXPECT_EQ(wordsAt(fb, 1, 0), w);
    EXPECT_EQ(wordsAt(fb, 2, 0), w);
  }
  static constexpr PixelRect kRegion{1, 0, 3, 1};
};

TEST_P(AccumRegion, Load) {
  Framebuffer fb = fresh();
  accumulate(fb, kRegion, AccumOp::Load, 1.0f, kAllChannels);
  expectInside(fb, {32767, 32767, 32767, alphaWord(32767)});  // white -> 1.0 * 32767
  expectOutsideUntouched(fb);
}

TEST_P(AccumRegion, Accum) {
  Framebuffer fb = fresh();
  accumulate(fb, kRegion, AccumOp::Accum, 0.5f, kAllChannels);
  // 1.0 * 16383.5 -> 16383; 1000 + 16383 = 17383
  expectInside(fb, {17383, 17383, 17383, alphaWord(17383)});
  expectOutsideUntouched(fb);
}

TEST_P(AccumRegion, Mult) {
  Framebuffer fb = fresh();
  accumulate(fb, kRegion, AccumOp::Mult, 0.5f, kAllChannels);
  expectInside(fb, {500, 500, 500, alphaWord(500)});  // 1000 * 0.5
  expectOutsideUntouched(fb);
}

TEST_P(AccumRegion, Add) {
  Framebuffer fb = fresh();
  accumulate(fb, kRegion, AccumOp::Add, 0.25f, kAllChannels);
  // increment 0.25 * 32767 = 8191.75 -> 8191; 1000 + 8191 = 9191
  expectInside(fb, {9191, 9191, 9191, alphaWord(9191)});
  expectOutsideUntouched(fb);
}

TEST_P(AccumRegion, Return) {
  Framebuffer fb = fresh();
  accumulate(fb, kRegion, AccumOp::Return, 1.0f, kAllChannels);
  // 1000 / 32767 * 255 = 7.782 -> 8; indigo keeps the destination alpha 255
  const Rgba8 inside{8, 8, 8, GetParam() ? std::uint8_t{8} : std::uint8_t{255}};
  EXPECT_EQ(fb.color(1, 0), inside);
  EXPECT_EQ(fb.color(2, 0), inside);
  expectInside(fb, {1000, 1000, 1000, alphaWord(1000)});
  expectOutsideUntouched(fb);
}

TEST_P(AccumRegion, RegionIsClippedToTheWindow) {
  Framebuffer fb = fresh();
  accumulate(fb, PixelRect{-5, -5, 2, 1}, AccumOp::Mult, 0.5f, kAllChannels);  // pixels (0,0), (1,0)
  accumulate(fb, PixelRect{3, 0, 9, 9}, AccumOp::Mult, 0.0f, kAllChannels);    // nothing
  accumulate(fb, PixelRect{2, 1, 2, 2}, AccumOp::Mult, 0.0f, kAllChannels);    // empty
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{500, 500, 500, alphaWord(500)}));
  EXPECT_EQ(wordsAt(fb, 1, 0), (Words{500, 500, 500, alphaWord(500)}));
  EXPECT_EQ(wordsAt(fb, 2, 0), (Words{1000, 1000, 1000, alphaWord(1000)}));
  for (int x = 0; x < 3; ++x) EXPECT_EQ(wordsAt(fb, x, 1), (Words{1000, 1000, 1000, alphaWord(1000)}));
}

INSTANTIATE_TEST_SUITE_P(AccumBothProfiles, AccumRegion, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "mesa" : "indigo"; });

TEST(AccumReturn, ColourMaskKeepsTheMaskedChannels) {
  Framebuffer mesa(1, 1, mesaProfile()), indigo(1, 1, indigoProfile());
  mesa.color(0, 0) = indigo.color(0, 0) = {10, 20, 30, 40};
  setWords(mesa, 0, 0, {16384, 16384, 16384, 16384});
  setWords(indigo, 0, 0, {16384, 16384, 16384, 0});
  accumulate(mesa, mesa.bounds(), AccumOp::Return, 1.0f, {true, false, true, false});
  // 16384 / 32767 * 255 = 127.504 -> 128 for R and B; G and A keep 20 and 40
  EXPECT_EQ(mesa.color(0, 0), (Rgba8{128, 20, 128, 40}));
  accumulate(mesa, mesa.bounds(), AccumOp::Return, 1.0f, {false, true, false, true});
  EXPECT_EQ(mesa.color(0, 0), (Rgba8{128, 128, 128, 128}));
  accumulate(indigo, indigo.bounds(), AccumOp::Return, 1.0f, {false, true, false, true});
  // only G is written; R and B masked; alpha has no word at all
  EXPECT_EQ(indigo.color(0, 0), (Rgba8{10, 128, 30, 40}));
}

TEST(AccumReturn, MaskDoesNotRestrictTheOtherOperations) {
  // The colour mask only gates GL_RETURN's writes: LOAD reads every channel.
  Framebuffer fb(1, 1, mesaProfile());
  fb.color(0, 0) = {255, 255, 255, 255};
  accumulate(fb, fb.bounds(), AccumOp::Load, 1.0f, {false, false, false, false});
  EXPECT_EQ(wordsAt(fb, 0, 0), (Words{32767, 32767, 32767, 32767}));
}

TEST(AccumClear, WordsFollowMesasFloatToShort) {
  // ((int)(65535 * v) - 1) / 2, C division truncating toward zero
  EXPECT_EQ(accumClearWord(1.0f), 32767);    // (65535 - 1) / 2
  EXPECT_EQ(accumClearWord(-1.0f), -32768);  // (-65535 - 1) / 2
  EXPECT_EQ(accumClearWord(0.0f), 0);        // (0 - 1) / 2 = 0, not -1
  EXPECT_EQ(accumClearWord(0.5f), 16383);    // 32767.5 -> 32767; 32766 / 2
  EXPECT_EQ(accumClearWord(-0.5f), -16384);  // -32767.5 -> -32767; -32768 / 2
  EXPECT_EQ(accumClearWord(0.25f), 8191);    // 16383.75 -> 16383; 16382 / 2
  EXPECT_EQ(accumClearWord(0.1f), 3276);     // 6553.5 -> 6553; 6552 / 2
  EXPECT_EQ(accumClearWord(-0.1f), -3277);   // -6553; -6554 / 2
  EXPECT_EQ(accumClearWord(1e-5f), 0);       // 0.655 -> 0; -1 / 2 = 0
  EXPECT_EQ(accumClearWord(-1e-5f), 0);      // -0.655 -> 0; -1 / 2 = 0
  EXPECT_EQ(accumClearWord(4.57770657e-05f), 1);    // 3 / 65535: 65535 * v = 3.0; 2 / 2
  EXPECT_EQ(accumClearWord(-4.57770657e-05f), -2);  // -3; -4 / 2
}

TEST(AccumClear, IndigoClearsThreeWordsAndMesaFour) {
  ClearValues v;
  v.accum = {accumClearWord(0.5f), accumClearWord(-0.5f), accumClearWord(0.1f), accumClearWord(1.0f)};
  ClearBuffers which;
  which.accum = true;
  Framebuffer mesa(2, 1, mesaProfile()), indigo(2, 1, indigoProfile());
  clearBuffers(mesa, PixelRect{1, 0, 2, 1}, which, v, ClearMasks{});
  clearBuffers(indigo, PixelRect{1, 0, 2, 1}, which, v, ClearMasks{});
  EXPECT_EQ(wordsAt(mesa, 1, 0), (Words{16383, -16384, 3276, 32767}));
  EXPECT_EQ(wordsAt(indigo, 1, 0), (Words{16383, -16384, 3276, 0}));
  EXPECT_EQ(wordsAt(mesa, 0, 0), (Words{0, 0, 0, 0}));  // outside the region
  EXPECT_EQ(wordsAt(indigo, 0, 0), (Words{0, 0, 0, 0}));
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

// ---- every colour byte, every kind of value: the word arithmetic of the header
// comment, word by word, against accumulate's (which takes eight words at a
// time, pixels of odd rows included) -------------------------------------------

// (short)(float) as the header comment gives it, then wrapped (mesa), or
// clamped to +-40000 before saturating into a short, NaN giving 0 (indigo).
std::int16_t productOf(float f, bool wraps) {
  if (wraps) {
    const std::int32_t t = (f > -2147483648.0f && f < 2147483648.0f) ? static_cast<std::int32_t>(f) : INT32_MIN;
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(t & 0xFFFF));
  }
  if (std::isnan(f)) return 0;
  const float t = std::trunc(f);
  const std::int64_t c = t < -40000.0f ? -40000 : (t > 40000.0f ? 40000 : static_cast<std::int64_t>(t));
  return static_cast<std::int16_t>(c < -32768 ? -32768 : (c > 32767 ? 32767 : c));
}

std::int16_t sumOf(std::int16_t a, std::int16_t b, bool wraps) {
  const std::int32_t s = std::int32_t{a} + b;
  if (wraps) return static_cast<std::int16_t>(static_cast<std::uint16_t>(s & 0xFFFF));
  return static_cast<std::int16_t>(s < -32768 ? -32768 : (s > 32767 ? 32767 : s));
}

TEST(AccumBothProfiles, LoadAndAccumOfEveryByteAndValueAreTheWordArithmetic) {
  const float values[] = {1.0f, 0.5f, -1.0f, 0.25f, 1e-7f, -3.7f, 2.0f, 1e5f, -1e9f, 7e4f, 65537.0f / 32767.0f,
                          std::nextafter(std::numeric_limits<float>::max() / 32767.0f, 0.0f),
                          std::numeric_limits<float>::max() / 32767.0f, -std::numeric_limits<float>::max() / 32767.0f,
                          std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN()};
  std::mt19937 rng(20261205);
  int words = 0;
  for (const bool mesa : {true, false}) {
    const HardwareProfile& profile = mesa ? mesaProfile() : indigoProfile();
    const int channels = mesa ? 4 : 3;
    for (const int width : {1, 2, 7, 64}) {
      // Every byte in every channel: 256 pixels of colour, spread over rows.
      const int height = (256 + width - 1) / width;
      Framebuffer fb(width, height, profile);
      for (int i = 0; i < width * height; ++i) {
        const int x = i % width, y = i / width;
        fb.color(x, y) = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(255 - i % 256),
                          static_cast<std::uint8_t>(i * 7), static_cast<std::uint8_t>(rng())};
      }
      for (const AccumOp op : {AccumOp::Load, AccumOp::Accum})
        for (const float value : values) {
          std::vector<Words> before;
          for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
              const auto r = [&] { return static_cast<std::int16_t>(rng()); };
              setWords(fb, x, y, {r(), r(), r(), static_cast<std::int16_t>(mesa ? r() : 0)});
              before.push_back(wordsAt(fb, x, y));
            }
          // A region one column and one row in from the edges, where there are any.
          const PixelRect region{width > 2 ? 1 : 0, height > 2 ? 1 : 0, width, height};
          accumulate(fb, region, op, value, kAllChannels);
          const float scale = value * 32767.0f;
          for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
              Words expected = before[static_cast<std::size_t>(y * width + x)];
              const bool inside = x >= region.x0 && y >= region.y0;
              const bool skipped = op == AccumOp::Accum && value == 0.0f;
              for (int c = 0; c < channels && inside && !skipped; ++c) {
                const std::int16_t p = productOf(static_cast<float>(fb.color(x, y)[c]) * (1.0f / 255.0f) * scale, mesa);
                expected[c] = op == AccumOp::Load ? p : sumOf(expected[c], p, mesa);
              }
              ASSERT_EQ(wordsAt(fb, x, y), expected) << (mesa ? "mesa" : "indigo") << " width " << width << " op "
                                                     << static_cast<int>(op) << " value " << value << " pixel " << x
                                                     << "," << y;
              words += 4;
            }
        }
    }
  }
  EXPECT_GT(words, 100000);
}

}  // namespace
}  // namespace mpr
