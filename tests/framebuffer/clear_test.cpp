// glClear (GL 1.1 section 4.2.3) per pixel: only the pixels of the scissor
// box change; colour goes through the per-channel colour mask, depth through
// the depth mask, stencil through the stencil write mask (taken modulo the
// stencil width); the accumulation buffer has no mask, and an RGB-only
// (indigo) accumulation buffer keeps its alpha word at 0. Expected values are
// written by hand.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "framebuffer/clear.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "support/stencil_picture.hpp"

namespace mpr {
namespace {

using test::stencilMatches;

using Words = std::array<std::int16_t, 4>;

Words accumAt(const Framebuffer& fb, int x, int y) {
  const std::int16_t* a = fb.accum(x, y);
  return {a[0], a[1], a[2], a[3]};
}

constexpr ClearBuffers kAll{true, true, true, true};

// A 6x4 window whose every buffer holds a recognisable pattern before the
// clear: stencil 10 y + x + 1, colour (x, y, 7, 9), depth 0x100 + x + 16 y,
// accumulation words (x, y, -1, -2) (the alpha word set by hand as well).
Framebuffer patterned(const HardwareProfile& p = indigoProfile()) {
  Framebuffer fb(6, 4, p);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) {
      fb.stencil(x, y) = static_cast<std::uint8_t>(10 * y + x + 1);
      fb.color(x, y) = Rgba8{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 7, 9};
      fb.depth(x, y) = static_cast<std::uint32_t>(0x100 + x + 16 * y);
      std::int16_t* a = fb.accum(x, y);
      a[0] = static_cast<std::int16_t>(x);
      a[1] = static_cast<std::int16_t>(y);
      a[2] = -1;
      a[3] = -2;
    }
  return fb;
}

ClearValues someValues() {
  ClearValues v;
  v.color = {200, 150, 100, 50};
  v.depth = 0xABCDEF;
  v.stencil = 7;
  v.accum = {1000, -2000, 3000, -4000};
  return v;
}

// ---------------------------------------------------------------------------
// The scissor box
// ---------------------------------------------------------------------------

TEST(ClearScissor, OnlyPixelsInsideChange) {
  // Scissor [1, 4) x [1, 3): pixels x = 1..3, y = 1..2. Mesa profile so that
  // all four accumulation words are cleared.
  Framebuffer fb = patterned(mesaProfile());
  clearBuffers(fb, PixelRect{1, 1, 4, 3}, kAll, someValues(), ClearMasks{});
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    31 32 33 34 35 36
    21  7  7  7 25 26
    11  7  7  7 15 16
     1  2  3  4  5  6
  )"));
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) {
      const bool inside = x >= 1 && x <= 3 && y >= 1 && y <= 2;
      SCOPED_TRACE(::testing::Message() << "pixel (" << x << "," << y << ")");
      if (inside) {
        EXPECT_EQ(fb.color(x, y), (Rgba8{200, 150, 100, 50}));
        EXPECT_EQ(fb.depth(x, y), 0xABCDEFu);
        EXPECT_EQ(accumAt(fb, x, y), (Words{1000, -2000, 3000, -4000}));
      } else {
        EXPECT_EQ(fb.color(x, y), (Rgba8{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 7, 9}));
        EXPECT_EQ(fb.depth(x, y), static_cast<std::uint32_t>(0x100 + x + 16 * y));
        EXPECT_EQ(accumAt(fb, x, y), (Words{static_cast<std::int16_t>(x), static_cast<std::int16_t>(y), -1, -2}));
      }
    }
}

TEST(ClearScissor, BoxReachingOutsideIsClipped) {
  // [-2, 2) x [-2, 2) covers only pixels x, y = 0..1 of the window;
  // [4, 99) x [3, 99) only x = 4..5, y = 3.
  Framebuffer fb = patterned();
  ClearBuffers which;
  which.stencil = true;
  clearBuffers(fb, PixelRect{-2, -2, 2, 2}, which, someValues(), ClearMasks{});
  clearBuffers(fb, PixelRect{4, 3, 99, 99}, which, someValues(), ClearMasks{});
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    31 32 33 34  7  7
    21 22 23 24 25 26
     7  7 13 14 15 16
     7  7  3  4  5  6
  )"));
}

TEST(ClearScissor, EmptyOrOutsideBoxClearsNothing) {
  Framebuffer fb = patterned();
  clearBuffers(fb, PixelRect{3, 3, 3, 5}, kAll, someValues(), ClearMasks{});    // zero width
  clearBuffers(fb, PixelRect{2, 2, 5, 2}, kAll, someValues(), ClearMasks{});    // zero height
  clearBuffers(fb, PixelRect{6, 0, 10, 4}, kAll, someValues(), ClearMasks{});   // right of the window
  clearBuffers(fb, PixelRect{0, -5, 6, 0}, kAll, someValues(), ClearMasks{});   // below it
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    31 32 33 34 35 36
    21 22 23 24 25 26
    11 12 13 14 15 16
     1  2  3  4  5  6
  )"));
  EXPECT_EQ(fb.color(0, 0), (Rgba8{0, 0, 7, 9}));
  EXPECT_EQ(fb.depth(5, 3), static_cast<std::uint32_t>(0x100 + 5 + 48));
}

TEST(ClearScissor, OnlyTheNamedBuffers) {
  // Clearing the stencil alone leaves colour, depth and accumulation as they were.
  Framebuffer fb = patterned();
  ClearBuffers which;
  which.stencil = true;
  clearBuffers(fb, fb.bounds(), which, someValues(), ClearMasks{});
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    7 7 7 7 7 7
    7 7 7 7 7 7
    7 7 7 7 7 7
    7 7 7 7 7 7
  )"));
  EXPECT_EQ(fb.color(2, 1), (Rgba8{2, 1, 7, 9}));
  EXPECT_EQ(fb.depth(2, 1), 0x100u + 2 + 16);
  EXPECT_EQ(accumAt(fb, 2, 1), (Words{2, 1, -1, -2}));
  // And colour alone leaves the stencil.
  which = ClearBuffers{};
  which.color = true;
  ClearValues v = someValues();
  v.stencil = 99;
  clearBuffers(fb, fb.bounds(), which, v, ClearMasks{});
  EXPECT_EQ(fb.color(2, 1), (Rgba8{200, 150, 100, 50}));
  EXPECT_EQ(fb.stencil(2, 1), 7);
}

// ---------------------------------------------------------------------------
// Write masks
// ---------------------------------------------------------------------------

TEST(ClearMasks, ColourMaskPerChannel) {
  // Pixel x is cleared with colour mask x (bit 0 = R ... bit 3 = A): each
  // channel is the clear value (200, 150, 100, 50) where its bit is on and
  // the old (1, 2, 3, 4) where it is off.
  Framebuffer fb(16, 1, indigoProfile());
  for (int x = 0; x < 16; ++x) fb.color(x, 0) = Rgba8{1, 2, 3, 4};
  ClearBuffers which;
  which.color = true;
  for (int x = 0; x < 16; ++x) {
    ClearMasks m;
    m.color = {(x & 1) != 0, (x & 2) != 0, (x & 4) != 0, (x & 8) != 0};
    clearBuffers(fb, PixelRect{x, 0, x + 1, 1}, which, someValues(), m);
  }
  const std::array<Rgba8, 16> expected = {{
      {1, 2, 3, 4},       {200, 2, 3, 4},       {1, 150, 3, 4},       {200, 150, 3, 4},
      {1, 2, 100, 4},     {200, 2, 100, 4},     {1, 150, 100, 4},     {200, 150, 100, 4},
      {1, 2, 3, 50},      {200, 2, 3, 50},      {1, 150, 3, 50},      {200, 150, 3, 50},
      {1, 2, 100, 50},    {200, 2, 100, 50},    {1, 150, 100, 50},    {200, 150, 100, 50},
  }};
  for (int x = 0; x < 16; ++x) EXPECT_EQ(fb.color(x, 0), expected[x]) << "mask " << x;
}

TEST(ClearMasks, DepthMaskOffKeepsDepth) {
  Framebuffer fb = patterned();
  ClearMasks m;
  m.depth = false;
  clearBuffers(fb, fb.bounds(), kAll, someValues(), m);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) {
      EXPECT_EQ(fb.depth(x, y), static_cast<std::uint32_t>(0x100 + x + 16 * y));
      EXPECT_EQ(fb.color(x, y), (Rgba8{200, 150, 100, 50}));  // the other buffers still clear
      EXPECT_EQ(fb.stencil(x, y), 7);
    }
  m.depth = true;
  clearBuffers(fb, fb.bounds(), kAll, someValues(), m);
  EXPECT_EQ(fb.depth(5, 3), 0xABCDEFu);
}

TEST(ClearMasks, StencilWriteMaskKeepsUnmaskedBits) {
  // Stored 0xA5 = 1010 0101 everywhere, clear value 0x3C = 0011 1100.
  // Column x is cleared with write mask:
  //   x = 0: 0x0F -> high bits of 0xA5, low of 0x3C: 0xAC = 172
  //   x = 1: 0xF0 -> 0x30 | 0x05 = 0x35 = 53
  //   x = 2: 0x00 -> 0xA5 = 165 (nothing)
  //   x = 3: 0xFF -> 0x3C = 60
  //   x = 4: 0x01 -> bit 0 from 0x3C (0): 0xA4 = 164
  //   x = 5: 0x80 -> bit 7 from 0x3C (0): 0x25 = 37
  //   x = 6: 0x10 -> bit 4 from 0x3C (1): 0xB5 = 181
  const std::array<std::uint32_t, 7> masks = {0x0F, 0xF0, 0x00, 0xFF, 0x01, 0x80, 0x10};
  Framebuffer fb(7, 2, indigoProfile());
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 7; ++x) fb.stencil(x, y) = 0xA5;
  ClearBuffers which;
  which.stencil = true;
  ClearValues v;
  v.stencil = 0x3C;
  for (int x = 0; x < 7; ++x) {
    ClearMasks m;
    m.stencil = masks[x];
    clearBuffers(fb, PixelRect{x, 0, x + 1, 2}, which, v, m);
  }
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    172 53 165 60 164 37 181
    172 53 165 60 164 37 181
  )"));
}

// ---------------------------------------------------------------------------
// Accumulation buffer
// ---------------------------------------------------------------------------

TEST(ClearAccum, IgnoresEveryWriteMask) {
  // All masks off: colour, depth and stencil keep their patterns, the
  // accumulation words are cleared anyway (GL has no accumulation mask).
  Framebuffer fb = patterned(mesaProfile());
  ClearMasks m;
  m.color = {false, false, false, false};
  m.depth = false;
  m.stencil = 0;
  clearBuffers(fb, fb.bounds(), kAll, someValues(), m);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) {
      EXPECT_EQ(accumAt(fb, x, y), (Words{1000, -2000, 3000, -4000}));
      EXPECT_EQ(fb.color(x, y), (Rgba8{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 7, 9}));
      EXPECT_EQ(fb.depth(x, y), static_cast<std::uint32_t>(0x100 + x + 16 * y));
    }
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    31 32 33 34 35 36
    21 22 23 24 25 26
    11 12 13 14 15 16
     1  2  3  4  5  6
  )"));
}

TEST(ClearAccum, IndigoIsRgbOnlyAndLeavesAlphaWordZero) {
  // indigo: three 16-bit words; the fourth stays 0 whatever the clear value.
  Framebuffer fb(3, 2, indigoProfile());
  ClearBuffers which;
  which.accum = true;
  clearBuffers(fb, fb.bounds(), which, someValues(), ClearMasks{});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_EQ(accumAt(fb, x, y), (Words{1000, -2000, 3000, 0}));
  ClearValues v = someValues();
  v.accum = {-32768, 32767, 0, 32767};
  clearBuffers(fb, fb.bounds(), which, v, ClearMasks{});
  EXPECT_EQ(accumAt(fb, 2, 1), (Words{-32768, 32767, 0, 0}));
}

TEST(ClearAccum, MesaHasAnAlphaWord) {
  Framebuffer fb(2, 1, mesaProfile());
  ClearBuffers which;
  which.accum = true;
  clearBuffers(fb, fb.bounds(), which, someValues(), ClearMasks{});
  EXPECT_EQ(accumAt(fb, 0, 0), (Words{1000, -2000, 3000, -4000}));
  EXPECT_EQ(accumAt(fb, 1, 0), (Words{1000, -2000, 3000, -4000}));
}

// ---------------------------------------------------------------------------
// A 4-bit stencil: the write mask is taken modulo the width
// ---------------------------------------------------------------------------

TEST(ClearStencilWidth, FourBitMaskModuloWidth) {
  HardwareProfile p = indigoProfile();
  p.name = "indigo-stencil4";
  p.stencilBits = 4;
  // Stored 12 = 1100 everywhere; clear value 9 = 1001 (already within 4 bits).
  //   column 0, mask ~0   -> 9 (every existing bit)
  //   column 1, mask 0xF0 -> no bit inside 4 bits: 12
  //   column 2, mask 0x13 -> acts as 0x3: (12 & ~3) | (9 & 3) = 12 | 1 = 13
  //   column 3, mask 0x0C -> (12 & 3) | (9 & 12) = 0 | 8 = 8
  Framebuffer fb(4, 1, p);
  for (int x = 0; x < 4; ++x) fb.stencil(x, 0) = 12;
  const std::array<std::uint32_t, 4> masks = {~0u, 0xF0, 0x13, 0x0C};
  ClearBuffers which;
  which.stencil = true;
  ClearValues v;
  v.stencil = 9;
  for (int x = 0; x < 4; ++x) {
    ClearMasks m;
    m.stencil = masks[x];
    clearBuffers(fb, PixelRect{x, 0, x + 1, 1}, which, v, m);
  }
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "9 12 13 8"));
}

}  // namespace
}  // namespace mpr
