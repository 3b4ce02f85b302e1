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

// Window coordinate to fixed point, rounding to nearest even as lrintf does.
inline std::int64_t snapToSubpixel(float windowCoord) {
  const double shifted = (static_cast<double>(windowCoord) - 0.5) * static_cast<double>(kSubpixelOne);
  return static_cast<std::int64_t>(std::nearbyint(shifted));
}

// Smallest integer n with n * 256 >= v, and largest with n * 256 <= v.
inline std::int64_t ceilDivSubpixel(std::int64_t v) { return -((-v) >> kSubpixelBits); }
inline std::int64_t floorDivSubpixel(std::int64_t v) { return v >> kSubpixelBits; }

}  // namespace mpr
