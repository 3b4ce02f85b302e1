#include "pipeline/fog.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace mpr {
namespace {

// 2^x as llvmpipe's fragment shader computes it (lp_bld_arit.c
// lp_build_exp2, Mesa 22.3): x clamped to [-126.99999, 128] (NaN kept), 2^floor(x) made
// from its exponent bits, times a degree-5 minimax polynomial of the
// fraction (lp_build_polynomial: even and odd terms in x^2 by Horner, then
// odd x + even), every step a single-precision operation, unfused.
float llvmpipeExp2(float x) {
  if (std::isnan(x)) return x;
  x = std::max(std::min(x, 128.0f), -126.99999f);
  const float whole = std::floor(x);
  const float fraction = x - whole;
  const std::int32_t exponent = (static_cast<std::int32_t>(whole) + 127) << 23;
  const float power = std::bit_cast<float>(exponent);
  constexpr float c[6] = {1.0f,
                          static_cast<float>(0.693153073200168932794),
                          static_cast<float>(0.240153617044375388211),
                          static_cast<float>(0.0558263180532956664775),
                          static_cast<float>(0.00898934009049466391101),
                          static_cast<float>(0.00187757667519147912699)};
  const float x2 = fraction * fraction;
  float odd = c[5], even = c[4];
  odd = c[3] + x2 * odd;
  even = c[2] + x2 * even;
  odd = c[1] + x2 * odd;
  even = c[0] + x2 * even;
  return power * (odd * fraction + even);
}

}  // namespace

float fogFactor(const FogState& fog, float c) {
  float f;
  switch (fog.mode) {
    case FogMode::Linear: {
      // Mesa's one multiply-add (prog_statevars.c STATE_FOG_PARAMS_OPTIMIZED,
      // ff_fragment_shader.cpp): c * p0 + p1 with p0 = -1 / (end - start)
      // and p1 = end * -p0, in single precision, unfused (llvmpipe lowers
      // ffma); GL leaves start = end open, where Mesa takes p0 = 1, so f =
      // c - end, clamped (measured, fog_linear_start_equals_end.gls).
      const float p0 = fog.end == fog.start ? 1.0f : -1.0f / (fog.end - fog.start);
      const float p1 = fog.end * -p0;
      const float product = c * p0;
      f = product + p1;
      break;
    }
    // Mesa's program takes 2^x for e^x (STATE_FOG_PARAMS_OPTIMIZED: the
    // density times log2 e, or times 1 / sqrt(ln 2), in double, rounded to
    // float), llvmpipe's 2^x at that.
    case FogMode::Exp:
      f = llvmpipeExp2(-(c * static_cast<float>(static_cast<double>(fog.density) * 1.4426950408889634074)));
      break;
    case FogMode::Exp2: {
      const float dc = c * static_cast<float>(static_cast<double>(fog.density) * 1.2011224087864498);
      f = llvmpipeExp2(-(dc * dc));
      break;
    }
    default:
      f = 1.0f;
  }
  if (std::isnan(f)) return 1.0f;
  return std::clamp(f, 0.0f, 1.0f);
}

Vec4 applyFog(const FogState& fog, float f, const Vec4& color) {
  const float g = 1.0f - f;
  return Vec4(f * color.r + g * fog.color.r, f * color.g + g * fog.color.g, f * color.b + g * fog.color.b, color.a);
}

}  // namespace mpr
