#include "pipeline/fog.hpp"

#include <algorithm>
#include <cmath>

namespace mpr {

float fogFactor(const FogState& fog, float c) {
  float f;
  switch (fog.mode) {
    case FogMode::Linear:
      // GL leaves start = end open. Mesa evaluates linear fog as one
      // multiply-add, c * -1/(end - start) + end/(end - start), and there
      // takes the first constant as 1 and the second as end * -1
      // (prog_statevars.c, STATE_FOG_PARAMS_OPTIMIZED): f = c - end, clamped
      // (measured, fog_linear_start_equals_end.gls).
      f = fog.end == fog.start ? c - fog.end : (fog.end - c) / (fog.end - fog.start);
      break;
    case FogMode::Exp:
      f = std::exp(-(fog.density * c));
      break;
    case FogMode::Exp2: {
      const float dc = fog.density * c;
      f = std::exp(-(dc * dc));
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
