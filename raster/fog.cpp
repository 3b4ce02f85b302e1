#include "raster/fog.hpp"

#include <algorithm>
#include <cmath>

#include "raster/llvmpipe_math.hpp"

namespace mpr {

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
