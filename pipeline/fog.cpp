#include "pipeline/fog.hpp"

#include <algorithm>
#include <cmath>

namespace mpr {

float fogFactor(const FogState& fog, float c) {
  float f;
  switch (fog.mode) {
    case FogMode::Linear:
      if (fog.end == fog.start) return c < fog.end ? 1.0f : 0.0f;
      f = (fog.end - c) / (fog.end - fog.start);
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
