#pragma once
// Deterministic samples for the reference. Every number is a hash of (pixel,
// sample index, dimension), never of a thread or of an order of work, so a
// pixel's value is the same at any thread count and on every run.
#include <cmath>
#include <cstdint>

#include "util/vecmath.hpp"

namespace mpr {

// SplitMix64's finaliser (Steele et al. 2014): a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// A uniform double in [0, 1) from the top 53 bits.
constexpr double unitFromBits(std::uint64_t v) { return static_cast<double>(v >> 11) * 0x1.0p-53; }

// Kensler's hashed permutation of [0, n) ("Correlated Multi-Jittered
// Sampling", 2013, listing 3): permute(i) is a bijection for each seed.
constexpr std::uint32_t permute(std::uint32_t i, std::uint32_t n, std::uint32_t seed) {
  std::uint32_t w = n - 1;
  w |= w >> 1, w |= w >> 2, w |= w >> 4, w |= w >> 8, w |= w >> 16;
  do {
    i ^= seed; i *= 0xe170893d; i ^= seed >> 16; i ^= (i & w) >> 4; i ^= seed >> 8; i *= 0x0929eb3f;
    i ^= seed >> 23; i ^= (i & w) >> 1; i *= 1 | seed >> 27; i *= 0x6935fa69; i ^= (i & w) >> 11;
    i *= 0x74dcb303; i ^= (i & w) >> 2; i *= 0x9e501cc3; i ^= (i & w) >> 2; i *= 0xc860a3df;
    i &= w; i ^= i >> 5;
  } while (i >= n);
  return (i + seed) % n;
}

// The rows x columns of a jittered grid of n cells: the largest divisor of n
// not above sqrt(n) (16 -> 4x4, 8 -> 2x4, 7 -> 1x7).
inline void gridOf(std::uint32_t n, std::uint32_t& rows, std::uint32_t& cols) {
  rows = 1;
  for (std::uint32_t r = 1; r * r <= n; ++r)
    if (n % r == 0) rows = r;
  cols = n / rows;
}

// Dimensions of a sample path: the pixel position, then per specular depth
// its light-disc strata and its frosted-glass perturbation.
enum : std::uint32_t {
  kDimPixel = 0,
  kDimLight = 0x100,
  kDimFrost = 0x10000,
  kDimLens = 0x20000,
  kDimFrostLight = 0x30000,
  kDimsPerDepth = 0x40
};

struct PixelSampler {
  std::uint32_t x = 0, y = 0, samples = 1;

  double uniform(std::uint32_t sample, std::uint32_t dim) const {
    const std::uint64_t key = (static_cast<std::uint64_t>(x) << 40) ^ (static_cast<std::uint64_t>(y) << 16) ^ sample;
    return unitFromBits(mix64(mix64(key + 0x9e3779b97f4a7c15ull) ^ (static_cast<std::uint64_t>(dim) * 0xd1b54a32d192ed03ull)));
  }
  std::uint32_t seed(std::uint32_t dim) const {
    return static_cast<std::uint32_t>(mix64((static_cast<std::uint64_t>(x) << 32 | y) ^ (0xa0761d6478bd642full * (dim + 1))));
  }

  // Sample `i`'s position inside the pixel, in [0, 1)^2: cell i of the
  // jittered grid, jittered uniformly.
  DVec2 pixelOffset(std::uint32_t i) const {
    std::uint32_t rows, cols;
    gridOf(samples, rows, cols);
    const std::uint32_t r = i / cols, c = i % cols;
    return {(c + uniform(i, kDimPixel)) / cols, (r + uniform(i, kDimPixel + 1)) / rows};
  }

  // Point k of the `perSample` points that sample i takes on an area light at
  // specular depth `depth`: the pixel's samples * perSample points share one
  // jittered grid, dealt out by a per-pixel permutation, so the light is
  // stratified over the pixel whatever the split.
  DVec2 lightPoint(std::uint32_t i, std::uint32_t k, std::uint32_t perSample, std::uint32_t depth) const {
    const std::uint32_t n = samples * perSample, dim = kDimLight + depth * kDimsPerDepth;
    std::uint32_t rows, cols;
    gridOf(n, rows, cols);
    const std::uint32_t cell = permute(i * perSample + k, n, seed(dim));
    return {(cell % cols + uniform(i, dim + 2 * k)) / cols, (cell / cols + uniform(i, dim + 2 * k + 1)) / rows};
  }

  // Sample i's point on the lens, in [0, 1)^2: the pixel's samples share one
  // jittered grid, dealt out by a per-pixel permutation (so the lens and the
  // pixel position are stratified independently).
  DVec2 lensPoint(std::uint32_t i) const {
    std::uint32_t rows, cols;
    gridOf(samples, rows, cols);
    const std::uint32_t cell = permute(i, samples, seed(kDimLens));
    return {(cell % cols + uniform(i, kDimLens)) / cols, (cell / cols + uniform(i, kDimLens + 1)) / rows};
  }

  // Two independent standard normal values for sample i (Box-Muller).
  DVec2 gaussian(std::uint32_t i, std::uint32_t depth) const { return normalPair(i, kDimFrost + 2 * depth); }

  // The pair that scatters light point k's passage through a frosted face,
  // for sample i at specular depth `depth` (independent of the view's).
  DVec2 lightScatter(std::uint32_t i, std::uint32_t k, std::uint32_t depth) const {
    return normalPair(i, kDimFrostLight + depth * kDimsPerDepth + 2 * (k % (kDimsPerDepth / 2)));
  }

 private:
  DVec2 normalPair(std::uint32_t i, std::uint32_t dim) const {
    const double u1 = 1.0 - uniform(i, dim), u2 = uniform(i, dim + 1);
    const double r = std::sqrt(-2.0 * std::log(u1)), a = 6.283185307179586 * u2;
    return {r * std::cos(a), r * std::sin(a)};
  }
};

// Shirley and Chiu's concentric map of the unit square onto the unit disc:
// area-preserving, so strata of the square stay strata of the disc.
inline DVec2 concentricDisc(DVec2 u) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};
  constexpr double quarterPi = 0.7853981633974483;
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) r = a, phi = quarterPi * (b / a);
  else r = b, phi = 2.0 * quarterPi - quarterPi * (a / b);
  return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace mpr
