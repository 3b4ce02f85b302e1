#pragma once
// llvmpipe's transcendental functions (gallivm lp_bld_arit.c, Mesa 22.3),
// bit for bit: the approximations its shaders run where GL says e^x, log or
// pow, single precision, in its order of operations. Mesa's fixed-function
// programs reach them through fog (2^x) and lighting (LIT's and the spot
// cone's pow).
#include "util/vecmath.hpp"

namespace mpr {

// A program's DP3 as llvmpipe runs it: nir_lower_alu_to_scalar splits fdot3
// into products summed from the last channel, (a.z b.z + a.y b.y) + a.x b.x.
inline float llvmpipeDot3(const Vec3& a, const Vec3& b) { return a.z * b.z + a.y * b.y + a.x * b.x; }

// lp_build_exp2: x clamped to [-126.99999, 128] (NaN kept), 2^floor(x) from
// exponent bits times a degree-5 minimax polynomial of the fraction.
float llvmpipeExp2(float x);

// lp_build_log2_safe: exponent plus y P(y^2), y = (m - 1) / (m + 1) for the
// mantissa m in [1, 2), the last step fused; -inf at 0, +inf at +inf, NaN
// below 0.
float llvmpipeLog2(float x);

// lp_build_pow: 0 where x is 0, else exp2(log2(x) * y).
float llvmpipePow(float x, float y);

}  // namespace mpr
