// llvmpipe's 2^x, log2 and pow (pipeline/llvmpipe_math): the values their
// construction makes exact, the edge cases lp_bld_arit.c defines, and the
// approximation's error against libm (the minimax polynomials' own error,
// a few parts in 10^7, not a tolerance of ours). Their bits against
// llvmpipe itself are held by the conformance reproducers
// (fog_exp2_polynomial.gls, fog_exp_polynomial_fused.gls,
// lighting_program_order.gls).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "raster/llvmpipe_math.hpp"

namespace mpr {
namespace {

TEST(LlvmpipeMath, Exp2OfAnIntegerIsThatPowerOfTwo) {
  // The fraction is 0 and the polynomial's first coefficient is 1.
  for (int k = -126; k <= 127; ++k) EXPECT_EQ(llvmpipeExp2(static_cast<float>(k)), std::ldexp(1.0f, k)) << k;
}

TEST(LlvmpipeMath, Exp2ClampsItsArgumentAndKeepsNaN) {
  EXPECT_EQ(llvmpipeExp2(-1000.0f), llvmpipeExp2(-126.99999f));
  EXPECT_EQ(llvmpipeExp2(1000.0f), llvmpipeExp2(128.0f));
  EXPECT_TRUE(std::isinf(llvmpipeExp2(128.0f)));  // 2^128: the exponent bits of infinity
  EXPECT_TRUE(std::isnan(llvmpipeExp2(std::numeric_limits<float>::quiet_NaN())));
}

TEST(LlvmpipeMath, Log2OfAPowerOfTwoIsItsExponent) {
  // The mantissa is 1, so y = 0 and the fused step returns the exponent.
  for (int k = -126; k <= 127; ++k) EXPECT_EQ(llvmpipeLog2(std::ldexp(1.0f, k)), static_cast<float>(k)) << k;
}

TEST(LlvmpipeMath, PolynomialStepsAreFusedMultiplyAdds) {
  // lp_build_polynomial's steps are lp_build_mad, an llvm.fmuladd that this
  // CPU fuses. Each input here was found where the fused evaluation and the
  // unfused one differ (values worked out beside the code, by exact
  // rational arithmetic rounded to single precision); the first is the
  // fog factor of fog_exp_polynomial_fused.gls's pixel.
  EXPECT_EQ(llvmpipeExp2(-0x1.832ad2p+0f), 0x1.66f27ep-2f);  // unfused: 0x1.66f28p-2
  EXPECT_EQ(llvmpipeLog2(0x1.91daecp-1f), -0x1.65dafep-2f);  // unfused: -0x1.65dbp-2
}

TEST(LlvmpipeMath, Log2EdgeCases) {
  EXPECT_EQ(llvmpipeLog2(0.0f), -std::numeric_limits<float>::infinity());
  EXPECT_EQ(llvmpipeLog2(std::numeric_limits<float>::infinity()), std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(llvmpipeLog2(-1.0f)));
}

TEST(LlvmpipeMath, PowIsZeroAtZeroAndExactOnPowersOfTwo) {
  EXPECT_EQ(llvmpipePow(0.0f, 0.0f), 0.0f);  // lp_build_pow selects 0 where x is 0
  EXPECT_EQ(llvmpipePow(0.0f, 5.0f), 0.0f);
  EXPECT_EQ(llvmpipePow(2.0f, 3.0f), 8.0f);
  EXPECT_EQ(llvmpipePow(0.5f, 4.0f), 0.0625f);
  EXPECT_EQ(llvmpipePow(0.75f, 0.0f), 1.0f);  // exp2(log2(x) * 0) = exp2(0)
}

TEST(LlvmpipeMath, TheApproximationsStayWithinTheirPolynomialsError) {
  double worstExp = 0.0, worstLog = 0.0;
  for (int i = 0; i <= 4000; ++i) {
    const float x = -10.0f + 20.0f * static_cast<float>(i) / 4000.0f;
    worstExp = std::max(worstExp, std::fabs(llvmpipeExp2(x) / std::exp2(static_cast<double>(x)) - 1.0));
    const float y = 0.01f + 10.0f * static_cast<float>(i) / 4000.0f;
    worstLog = std::max(worstLog, std::fabs(llvmpipeLog2(y) - std::log2(static_cast<double>(y))));
  }
  EXPECT_LT(worstExp, 3e-7);  // degree 5: about 2e-7 relative
  EXPECT_LT(worstLog, 2e-6);  // degree 4 in y^2: about 1e-6 absolute
  EXPECT_GT(worstExp, 0.0);   // an approximation, not libm
}

}  // namespace
}  // namespace mpr
