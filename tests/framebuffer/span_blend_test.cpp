// The span pipeline's blending (span::blendWords, on the bytes of colour
// words) against blend() (blend.hpp) one fragment at a time: for every pair
// of the eleven factors, every pair of source and destination values of
// each channel and every pair of alphas, the same four bytes.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>

#include "framebuffer/blend.hpp"
#include "framebuffer/fragment_span_stages.hpp"

namespace mpr {
namespace {

constexpr int kLanes = 64;

std::uint32_t wordOf(const Rgba8& c) {
  std::uint32_t w;
  std::memcpy(&w, &c, sizeof w);
  return w;
}

Rgba8 colorOf(std::uint32_t w) {
  Rgba8 c;
  std::memcpy(&c, &w, sizeof w);
  return c;
}

// Case i of 65536: a = i mod 256, b = i / 256. Channel 0 takes (a, b),
// channel 1 (b, a), channel 2 (255 - a, a ^ b) and the alphas (b ^ 0x5A, a):
// every pair of values in each channel, every pair of alphas, and every
// source alpha with every value of channel 0.
Rgba8 sourceOf(int i) {
  const auto a = static_cast<std::uint8_t>(i & 0xFF), b = static_cast<std::uint8_t>(i >> 8);
  return {a, b, static_cast<std::uint8_t>(255 - a), static_cast<std::uint8_t>(b ^ 0x5A)};
}
Rgba8 destinationOf(int i) {
  const auto a = static_cast<std::uint8_t>(i & 0xFF), b = static_cast<std::uint8_t>(i >> 8);
  return {b, a, static_cast<std::uint8_t>(a ^ b), a};
}

TEST(SpanBlend, EveryFactorPairAndChannelValueIsWhatBlendGives) {
  int pairs = 0;
  for (int src = 0; src <= static_cast<int>(BlendFactor::SrcAlphaSaturate); ++src)
    for (int dst = 0; dst <= static_cast<int>(BlendFactor::SrcAlphaSaturate); ++dst) {
      const BlendState state{true, static_cast<BlendFactor>(src), static_cast<BlendFactor>(dst)};
      ++pairs;
      int wrong = 0;
      for (int first = 0; first < 65536; first += kLanes) {
        alignas(64) std::uint32_t s[kLanes], d[kLanes];
        for (int k = 0; k < kLanes; ++k) {
          s[k] = wordOf(sourceOf(first + k));
          d[k] = wordOf(destinationOf(first + k));
        }
        // In place on the source, as the span pipeline calls it.
        span::blendWords<kLanes>(state, kLanes, s, d, s);
        for (int k = 0; k < kLanes; ++k) {
          const Rgba8 want = blend(state, sourceOf(first + k), destinationOf(first + k));
          if (colorOf(s[k]) != want && ++wrong <= 5)
            ADD_FAILURE() << "factors " << src << ", " << dst << " case " << first + k;
        }
      }
      ASSERT_EQ(wrong, 0);
    }
  EXPECT_EQ(pairs, 121);
}

// Only the first n words are written, whatever n is.
TEST(SpanBlend, WritesOnlyTheFirstNWords) {
  for (int n = 0; n <= kLanes; ++n) {
    alignas(64) std::uint32_t s[kLanes], d[kLanes], out[kLanes];
    for (int k = 0; k < kLanes; ++k) {
      s[k] = wordOf(sourceOf(977 * k + 5));
      d[k] = wordOf(destinationOf(613 * k + 11));
      out[k] = 0xDEADBEEFu;
    }
    span::blendWords<kLanes>(BlendState{true, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha}, n, s, d, out);
    for (int k = 0; k < kLanes; ++k) {
      if (k < n)
        EXPECT_EQ(colorOf(out[k]), blend(BlendState{true, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha},
                                         colorOf(s[k]), colorOf(d[k])))
            << "n " << n << " word " << k;
      else
        EXPECT_EQ(out[k], 0xDEADBEEFu) << "n " << n << " word " << k;
    }
  }
}

}  // namespace
}  // namespace mpr
