#pragma once
// Per-fragment operations in GL order (GL 1.1 chapter 4.1): pixel ownership
// and scissor (done by the caller through the raster bounds), alpha test,
// stencil test, depth test, stencil update, blending, colour write mask.
// Dithering is implementation-defined and not done (spec: scripts disable it).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "framebuffer/blend.hpp"
#include "framebuffer/compare_func.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/stencil.hpp"

namespace mpr {

struct AlphaTestState {
  bool enabled = false;
  CompareFunc func = CompareFunc::Always;
  float ref = 0.0f;  // clamped to [0, 1]
};

struct DepthTestState {
  bool enabled = false;
  CompareFunc func = CompareFunc::Less;
  bool writeMask = true;
};

struct FragmentState {
  AlphaTestState alpha;
  StencilState stencil;
  DepthTestState depth;
  BlendState blend;
  std::array<bool, 4> colorMask{true, true, true, true};
};

// One fragment as the rasterizer hands it over.
struct Fragment {
  int x, y;
  std::uint32_t depth;  // window depth as the stored integer
  Rgba8 color;          // already converted to the colour buffer's format
  float alpha;          // alpha before conversion (the alpha test converts it itself)
};

// What happened to one fragment, for statistics and the pass stepper.
enum class FragmentFate : std::uint8_t { AlphaFailed, StencilFailed, DepthFailed, Written };

// std::nearbyint for v >= 0 (or NaN) in the default rounding mode, inline
// instead of a libm call (a fifth of the fill paths' time): below 2^23,
// adding and taking off 2^23 rounds to an integer, to nearest even; from 2^23
// up every float is an integer already.
[[gnu::always_inline]] inline float roundNonNegative(float v) {
  constexpr float k2p23 = 8388608.0f;
  // Both computed, then one chosen: a select the compiler can do on vector
  // lanes (arithmetic inside a branch it may not speculate, trapping math).
  const float rounded = (v + k2p23) - k2p23;
  return v < k2p23 ? rounded : v;
}

// A window depth to the stored integer as llvmpipe's fragment shader writes
// it: clamped to [0, 1] ((0 < z) ? z : 0 takes NaN to 0), scaled in single
// precision, rounded to nearest even.
[[gnu::always_inline]] inline std::uint32_t windowDepthToWord(float z, float depthMax) {
  const float clamped = std::min(std::max(0.0f, z), 1.0f);
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(roundNonNegative(clamped * depthMax)));
}

// Float colour in [0, 1] to an 8-bit channel: clamp, scale, round to nearest even.
inline std::uint8_t floatToUnorm8(float c) {
  if (!(c > 0.0f)) return 0;  // also maps NaN to 0
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(roundNonNegative(c * 255.0f));
}

// The alpha test in the colour buffer's precision: GL 1.1 section 4.1.3
// converts ref to fixed point as an A component (section 2.13.9) and rounds
// the fragment's alpha likewise for the comparison (llvmpipe does the same, lp_bld_alpha.c
// lp_build_alpha_test; alpha_test_fixed_point.gls).
inline bool alphaTestPasses(const AlphaTestState& a, float alpha) {
  return compare(a.func, floatToUnorm8(alpha), floatToUnorm8(a.ref));
}

FragmentFate processFragment(const FragmentState& s, Framebuffer& fb, const Fragment& f);

}  // namespace mpr
