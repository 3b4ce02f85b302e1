// chooseFragmentPipeline's variants against processFragment: for every
// combination of alpha test, stencil test, depth test, blending and colour
// write mask (none, all, each single channel), random fragments on random
// buffers must leave the same fate, colour, depth and stencil, byte for byte,
// one by one and as spans.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/fragment_pipeline.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"

namespace mpr {
namespace {

constexpr int kSize = 8;
// The spans' window: rows longer than a span's capacity, so that spans of
// every length up to it (several vectors of lanes and a part) start
// anywhere on a row, up to its last pixel.
constexpr int kSpanWidth = FragmentSpan::kCapacity + 9, kSpanHeight = 3;

// A variant's state: bits 1, 2, 4, 8 turn the alpha test, stencil test,
// depth test and blending on.
FragmentState variantState(int bits, const std::array<bool, 4>& colorMask) {
  FragmentState s;
  s.alpha.enabled = (bits & 1) != 0;
  s.stencil.enabled = (bits & 2) != 0;
  s.depth.enabled = (bits & 4) != 0;
  s.blend.enabled = (bits & 8) != 0;
  s.colorMask = colorMask;
  return s;
}

// The tests' functions, references, operations and masks and the blend
// factors, at random (a variant is chosen by what is on, not by these).
void randomizeTests(FragmentState& s, std::mt19937& rng) {
  s.alpha.func = static_cast<CompareFunc>(rng() % 8);
  s.alpha.ref = static_cast<float>(rng() % 256) / 255.0f;
  s.blend.src = static_cast<BlendFactor>(rng() % 11);
  s.blend.dst = static_cast<BlendFactor>(rng() % 11);
  s.stencil.func = static_cast<CompareFunc>(rng() % 8);
  s.stencil.ref = rng() & 0xFF;
  s.stencil.valueMask = rng() & 0xFF;
  s.stencil.writeMask = rng() & 0xFF;
  s.stencil.sfail = static_cast<StencilOp>(rng() % 8);
  s.stencil.dpfail = static_cast<StencilOp>(rng() % 8);
  s.stencil.dppass = static_cast<StencilOp>(rng() % 8);
  s.depth.func = static_cast<CompareFunc>(rng() % 8);
  s.depth.writeMask = (rng() & 1) != 0;
}

// Random buffers, the same for the same seed.
void fillRandom(Framebuffer& fb, int seed) {
  std::mt19937 rng(static_cast<unsigned>(seed));
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) {
      fb.stencil(x, y) = static_cast<std::uint8_t>(rng() & 0xFF);
      fb.depth(x, y) = rng() & 0xFFFFFF;
      for (int c = 0; c < 4; ++c) fb.color(x, y)[c] = static_cast<std::uint8_t>(rng() & 0xFF);
    }
}

void expectSameBuffers(const Framebuffer& found, const Framebuffer& expected, int bits, int trial) {
  ASSERT_EQ(found.colorData(), expected.colorData()) << "variant " << bits << " trial " << trial;
  ASSERT_EQ(found.depthData(), expected.depthData()) << "variant " << bits << " trial " << trial;
  ASSERT_EQ(found.stencilData(), expected.stencilData()) << "variant " << bits << " trial " << trial;
}

TEST(FragmentPipeline, EveryVariantDoesWhatProcessFragmentDoes) {
  std::mt19937 rng(14);
  const std::array<std::array<bool, 4>, 6> masks = {{{false, false, false, false},
                                                     {true, true, true, true},
                                                     {true, false, false, false},
                                                     {false, true, false, false},
                                                     {false, false, true, false},
                                                     {false, false, false, true}}};
  int variants = 0;
  for (int bits = 0; bits < 16; ++bits)
    for (const auto& mask : masks) {
      FragmentState s = variantState(bits, mask);
      const FragmentFunction op = chooseFragmentPipeline(s).fragment;
      ++variants;
      for (int trial = 0; trial < 200; ++trial) {
        // A fresh random state of the tests for each fragment.
        randomizeTests(s, rng);
        Framebuffer expected(kSize, kSize, mesaProfile()), found(kSize, kSize, mesaProfile());
        fillRandom(expected, trial);
        fillRandom(found, trial);
        const Fragment f{static_cast<int>(rng() % kSize), static_cast<int>(rng() % kSize),
                         static_cast<std::uint32_t>(rng() & 0xFFFFFF),
                         Rgba8{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                               static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())},
                         static_cast<float>(rng() % 256) / 255.0f};
        const FragmentFate want = processFragment(s, expected, f);
        const FragmentFate got = op(s, found, f);
        ASSERT_EQ(got, want) << "variant " << bits << " trial " << trial;
        ASSERT_NO_FATAL_FAILURE(expectSameBuffers(found, expected, bits, trial));
      }
    }
  EXPECT_EQ(variants, 96);
}

// A span runs its fragments in order on one row: the same buffers and the
// same count of written fragments as processFragment one by one (a span
// from every start column, of every length that fits, half of them at most
// eight long, its lanes past the count random).
TEST(FragmentPipeline, EverySpanVariantDoesWhatProcessFragmentDoesInOrder) {
  std::mt19937 rng(1994);
  const std::array<std::array<bool, 4>, 3> masks = {
      {{false, false, false, false}, {true, true, true, true}, {false, true, false, true}}};
  int variants = 0;
  for (int bits = 0; bits < 16; ++bits)
    for (const auto& mask : masks) {
      FragmentState s = variantState(bits, mask);
      const SpanFunction op = chooseFragmentPipeline(s).span;
      ++variants;
      for (int trial = 0; trial < 100; ++trial) {
        randomizeTests(s, rng);
        Framebuffer expected(kSpanWidth, kSpanHeight, mesaProfile()), found(kSpanWidth, kSpanHeight, mesaProfile());
        fillRandom(expected, trial);
        fillRandom(found, trial);
        FragmentSpan span;
        span.x = static_cast<int>(rng() % kSpanWidth);
        span.y = static_cast<int>(rng() % kSpanHeight);
        // Every other span at most 8 long: those run over eight lanes of
        // their own (specialisedSpan's short body), the rest over padded ones.
        const int longest = std::min(trial % 2 == 0 ? 8 : FragmentSpan::kCapacity, kSpanWidth - span.x);
        span.count = 1 + static_cast<int>(rng() % static_cast<unsigned>(longest));
        // Every lane random: those past the count stand for whatever a
        // previous span left there; the span functions compute on them too,
        // and must neither count nor write them.
        for (int i = 0; i < FragmentSpan::kCapacity; ++i) {
          span.depth[i] = rng() & 0xFFFFFF;
          span.color[i] = Rgba8{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                                static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())};
          span.alpha[i] = static_cast<float>(rng() % 256) / 255.0f;
        }
        std::uint32_t want = 0;
        for (int i = 0; i < span.count; ++i) {
          const Fragment f{span.x + i, span.y, span.depth[i], span.color[i], span.alpha[i]};
          want += processFragment(s, expected, f) == FragmentFate::Written;
        }
        ASSERT_EQ(op(s, found, span), want) << "variant " << bits << " trial " << trial;
        ASSERT_NO_FATAL_FAILURE(expectSameBuffers(found, expected, bits, trial));
      }
    }
  EXPECT_EQ(variants, 48);
}

// The stencil test taken before shading (stencilRejectsAll): true exactly
// when no fragment of the run passes the stencil test, and then the buffers
// the fragments one by one leave (whatever their depth and colour); false
// otherwise, with nothing written. Runs of every length at every column, on
// rows of 73 pixels, of 16 (the vector loads' width) and of 9 (narrower
// than it: the plain loop), each function and mask, stencils that often
// hold one value per row (so that whole runs fail) and often not.
TEST(FragmentPipeline, TheStencilTestBeforeShadingRejectsExactlyTheRunsThatFailItEverywhere) {
  std::mt19937 rng(1997);
  std::array<int, 8> rejected{}, kept{};
  for (const int width : {kSpanWidth, 16, 9})
    for (int trial = 0; trial < 3000; ++trial) {
      FragmentState s = variantState(2 | static_cast<int>(rng() & 4) | static_cast<int>(rng() & 8),
                                     {true, true, true, true});
      randomizeTests(s, rng);
      s.stencil.func = static_cast<CompareFunc>(trial % 8);
      if (trial % 3 == 0) s.stencil.valueMask = ~0u;  // glStencilFunc's default: above the buffer's bits
      const StencilRejectFunction reject = chooseFragmentPipeline(s).stencilRejectsAll;
      ASSERT_NE(reject, nullptr);
      Framebuffer expected(width, kSpanHeight, mesaProfile()), found(width, kSpanHeight, mesaProfile());
      fillRandom(expected, trial);
      // Half the rows' values the reference (Equal passes, Notequal fails).
      const std::uint8_t a = static_cast<std::uint8_t>(rng() % 2 == 0 ? s.stencil.ref : rng()),
                         b = static_cast<std::uint8_t>(rng());
      for (int y = 0; y < kSpanHeight; ++y)
        for (int x = 0; x < width; ++x)
          expected.stencil(x, y) = trial % 2 == 0 ? a : (rng() % 8 == 0 ? b : a);
      found = expected;
      const Framebuffer before = expected;
      const int x = static_cast<int>(rng() % static_cast<unsigned>(width)), y = static_cast<int>(rng() % kSpanHeight);
      const int count = 1 + static_cast<int>(rng() % static_cast<unsigned>(std::min(FragmentSpan::kCapacity, width - x)));
      bool anyPasses = false;
      for (int i = 0; i < count; ++i) {
        anyPasses = anyPasses || stencilTest(s.stencil, expected.stencil(x + i, y));
        const Fragment f{x + i, y, static_cast<std::uint32_t>(rng() & 0xFFFFFF),
                         Rgba8{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                               static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())},
                         1.0f};
        ASSERT_TRUE(processFragment(s, expected, f) != FragmentFate::Written || anyPasses);
      }
      const bool r = reject(s, found, x, y, count);
      ASSERT_EQ(r, !anyPasses) << "width " << width << " trial " << trial;
      ASSERT_NO_FATAL_FAILURE(expectSameBuffers(found, r ? expected : before, width, trial));
      ++(r ? rejected : kept)[trial % 8];
    }
  // Both outcomes for every function that can have both (Never always
  // rejects, Always never does).
  for (int f = 1; f < 7; ++f) {
    EXPECT_GT(rejected[static_cast<std::size_t>(f)], 100) << "function " << f;
    EXPECT_GT(kept[static_cast<std::size_t>(f)], 100) << "function " << f;
  }
  EXPECT_EQ(kept[0], 0);
  EXPECT_EQ(rejected[7], 0);
}

// Only where the stencil test comes first and is on.
TEST(FragmentPipeline, TheStencilTestIsTakenBeforeShadingOnlyWhereItIsTheFirstTest) {
  for (int bits = 0; bits < 16; ++bits) {
    const FragmentState s = variantState(bits, {true, true, true, true});
    const bool first = (bits & 2) != 0 && (bits & 1) == 0;
    EXPECT_EQ(chooseFragmentPipeline(s).stencilRejectsAll != nullptr, first) << "variant " << bits;
  }
}

}  // namespace
}  // namespace mpr
