#pragma once
// Blending on 8-bit unsigned normalised colour (GL 1.1 section 4.1.6, the only
// equation GL 1.1 has: FUNC_ADD). Each product x*f/255 is taken as llvmpipe's
// unorm8 blender takes it (an integer approximation of rounding, see
// mulUnorm8), and the sum saturates.
#include <array>
#include <cstdint>

namespace mpr {

enum class BlendFactor : std::uint8_t {
  Zero, One, SrcColor, OneMinusSrcColor, DstColor, OneMinusDstColor,
  SrcAlpha, OneMinusSrcAlpha, DstAlpha, OneMinusDstAlpha, SrcAlphaSaturate,
};

using Rgba8 = std::array<std::uint8_t, 4>;

struct BlendState {
  bool enabled = false;
  BlendFactor src = BlendFactor::One;
  BlendFactor dst = BlendFactor::Zero;
};

// a * b / 255 for a, b in [0, 255] as llvmpipe's unorm8 multiply computes it
// (lp_build_mul_norm): t = a*b, (t + (t >> 8) + 128) >> 8. It equals
// round(a * b / 255) for all but 24 of the 65536 pairs, where it is one less
// (169 * 212 / 255 = 140.502 gives 140); measured against Mesa 22.3.6.
constexpr std::uint32_t mulUnorm8(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t t = a * b;
  return (t + (t >> 8) + 128u) >> 8;
}

// The factor for channel `c` (0..3) of the given source and destination colours.
constexpr std::uint32_t blendFactorValue(BlendFactor f, const Rgba8& s, const Rgba8& d, int c) {
  switch (f) {
    case BlendFactor::Zero: return 0;
    case BlendFactor::One: return 255;
    case BlendFactor::SrcColor: return s[c];
    case BlendFactor::OneMinusSrcColor: return 255u - s[c];
    case BlendFactor::DstColor: return d[c];
    case BlendFactor::OneMinusDstColor: return 255u - d[c];
    case BlendFactor::SrcAlpha: return s[3];
    case BlendFactor::OneMinusSrcAlpha: return 255u - s[3];
    case BlendFactor::DstAlpha: return d[3];
    case BlendFactor::OneMinusDstAlpha: return 255u - d[3];
    case BlendFactor::SrcAlphaSaturate: {
      // (f, f, f, 1) with f = min(As, 1 - Ad)
      if (c == 3) return 255;
      const std::uint32_t inv = 255u - d[3];
      return s[3] < inv ? s[3] : inv;
    }
  }
  return 0;
}

constexpr Rgba8 blend(const BlendState& b, const Rgba8& s, const Rgba8& d) {
  Rgba8 out{};
  for (int c = 0; c < 4; ++c) {
    const std::uint32_t v = mulUnorm8(s[c], blendFactorValue(b.src, s, d, c)) +
                            mulUnorm8(d[c], blendFactorValue(b.dst, s, d, c));
    out[c] = static_cast<std::uint8_t>(v > 255u ? 255u : v);
  }
  return out;
}

}  // namespace mpr
