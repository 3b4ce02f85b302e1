#include "raster/llvmpipe_math.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace mpr {
namespace {

// lp_build_polynomial: c0 + c1 x + c2 x^2 + ..., even and odd terms apart,
// each by Horner in x^2, then odd * x + even, every step an lp_build_mad
// (llvm.fmuladd, fused on a CPU with FMA; fog_exp_polynomial_fused.gls).
template <int N>
float polynomial(float x, const float (&c)[N]) {
  const float x2 = x * x;
  float even = 0.0f, odd = 0.0f;
  bool haveEven = false, haveOdd = false;
  for (int i = N - 1; i >= 0; --i) {
    if (i % 2 == 0) {
      even = haveEven ? std::fma(x2, even, c[i]) : c[i];
      haveEven = true;
    } else {
      odd = haveOdd ? std::fma(x2, odd, c[i]) : c[i];
      haveOdd = true;
    }
  }
  return haveOdd ? std::fma(odd, x, even) : even;
}

// lp_build_exp2_polynomial, EXP_POLY_DEGREE 5 (its first coefficient 1).
constexpr float kExp2[6] = {1.0f,
                            static_cast<float>(0.693153073200168932794),
                            static_cast<float>(0.240153617044375388211),
                            static_cast<float>(0.0558263180532956664775),
                            static_cast<float>(0.00898934009049466391101),
                            static_cast<float>(0.00187757667519147912699)};

// lp_build_log2_polynomial, LOG_POLY_DEGREE 4.
constexpr float kLog2[5] = {static_cast<float>(2.88539009343309178325),
                            static_cast<float>(0.961791550404184197881),
                            static_cast<float>(0.577440339438736392009),
                            static_cast<float>(0.403343858251329912514),
                            static_cast<float>(0.406718052498846252698)};

}  // namespace

float llvmpipeExp2(float x) {
  if (std::isnan(x)) return x;
  x = std::max(std::min(x, 128.0f), -126.99999f);
  const float whole = std::floor(x);
  const float fraction = x - whole;
  const float power = std::bit_cast<float>((static_cast<std::int32_t>(whole) + 127) << 23);
  return power * polynomial(fraction, kExp2);
}

float llvmpipeLog2(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  const float exponent = static_cast<float>(static_cast<std::int32_t>((bits & 0x7f800000u) >> 23) - 127);
  const float mantissa = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);
  const float y = (mantissa - 1.0f) / (mantissa + 1.0f);
  const float z = y * y;
  float result = std::fma(y, polynomial(z, kLog2), exponent);
  if (x >= std::numeric_limits<float>::infinity()) result = std::numeric_limits<float>::infinity();
  if (x == 0.0f) result = -std::numeric_limits<float>::infinity();
  if (x < 0.0f) result = std::numeric_limits<float>::quiet_NaN();
  return result;
}

float llvmpipePow(float x, float y) {
  if (x == 0.0f) return 0.0f;
  return llvmpipeExp2(llvmpipeLog2(x) * y);
}

}  // namespace mpr
