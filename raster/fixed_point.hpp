#pragma once
// Sub-pixel snapping: window coordinates are held with 8 fractional bits, as in
// Mesa's llvmpipe (FIXED_ORDER 8), so coverage is decided by exact integer
// arithmetic. The half-pixel offset is removed first, so pixel (px, py) samples
// at fixed-point (px << 8, py << 8).
#include <cmath>
#include <cstdint>

namespace mpr {

inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kSubpixelOne = std::int64_t{1} << kSubpixelBits;

// A rounded double to int64 without undefined behaviour: NaN gives 0 and
// magnitudes past 2^62 saturate there (so that differences stay
// representable). Values a render can reach (windows of 16384 pixels,
// viewports at int offsets) are far inside, so their results are unchanged;
// only NaN, infinite and w = 0 or denormal-w vertices and singular matrices
// reach the clamp: MPR's rasterizer drops those primitives before any
// product, and llvmpipe's set-up (llvmpipe_depth) wraps its products.
inline std::int64_t saturateToInt64(double rounded) {
  constexpr double kLimit = 4611686018427387904.0;  // 2^62
  if (!(rounded == rounded)) return 0;
  if (rounded >= kLimit) return std::int64_t{1} << 62;
  if (rounded <= -kLimit) return -(std::int64_t{1} << 62);
  return static_cast<std::int64_t>(rounded);
}

// Two's-complement wrap-around, as 64-bit integer hardware gives: the exact
// result wherever it fits, and a defined one (not undefined behaviour) for
// the clamped positions of non-finite or huge vertices, whose primitives no
// render draws.
inline std::int64_t wrappingAdd(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
inline std::int64_t wrappingSub(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
}
inline std::int64_t wrappingMul(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}

// Window coordinate to fixed point, rounding to nearest even as lrintf does.
inline std::int64_t snapToSubpixel(float windowCoord) {
  const double shifted = (static_cast<double>(windowCoord) - 0.5) * static_cast<double>(kSubpixelOne);
  return saturateToInt64(std::nearbyint(shifted));
}

// Smallest integer n with n * 256 >= v, and largest with n * 256 <= v.
inline std::int64_t ceilDivSubpixel(std::int64_t v) { return -((-v) >> kSubpixelBits); }
inline std::int64_t floorDivSubpixel(std::int64_t v) { return v >> kSubpixelBits; }

// floor(a / b) for b > 0.
inline std::int64_t floorDivide(std::int64_t a, std::int64_t b) { return a / b - (a % b != 0 && a < 0 ? 1 : 0); }

}  // namespace mpr
