#pragma once
// The stencil values the 1994 paper's Figure 4 works with, derived from the
// profile's stencil width ("Recursion" section): ZERO is the render area at
// every recursion level; levels 1, 2, ... mark the areas of enclosing
// recursion levels; SHAD_MIN is one-half and SHAD_ZERO three-quarters of the
// stencil range, so half of the range counts shadows and half holds levels.
// For 8 bits: SHAD_MIN = 128, SHAD_ZERO = 192.
#include <cstdint>

#include "framebuffer/profile.hpp"

namespace mpr {

struct StencilLevels {
  std::uint32_t zero = 0;       // ZERO: the render area
  std::uint32_t shadMin = 128;  // SHAD_MIN: one-half of the range
  std::uint32_t shadZero = 192; // SHAD_ZERO: three-quarters of the range
  std::uint32_t max = 255;      // the largest stencil value

  // Recursion levels use 1 .. SHAD_MIN - 1.
  int maxRecursionDepth() const { return static_cast<int>(shadMin) - 1; }
  // In-out counting about SHAD_ZERO stays inside (SHAD_MIN, max]: at most
  // this many volumes may enclose a point (entries above SHAD_ZERO) ...
  std::uint32_t maxShadowDepthAbove() const { return max - shadZero; }
  // ... and this many exits below it before the count would reach SHAD_MIN.
  std::uint32_t maxShadowDepthBelow() const { return shadZero - shadMin - 1; }
};

constexpr StencilLevels stencilLevelsForBits(int stencilBits) {
  const std::uint32_t range = 1u << stencilBits;
  return StencilLevels{0, range / 2, range / 4 * 3, range - 1};
}

inline StencilLevels stencilLevelsFor(const HardwareProfile& p) { return stencilLevelsForBits(p.stencilBits); }

}  // namespace mpr
