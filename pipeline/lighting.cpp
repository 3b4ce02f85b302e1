#include "pipeline/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace mpr {
namespace {

float dot3(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Vec3 normalized(const Vec3& v) {
  const float len = std::sqrt(dot3(v, v));
  return len > 0.0f ? v / len : v;
}

}  // namespace

Vec4 lightVertex(const LightingState& s, const Vec4& eye, const Vec3& normalIn, bool back) {
  const Material& m = s.material[back ? 1 : 0];
  const Vec3 n = back ? -normalIn : normalIn;
  const Vec3 v = eye.w != 0.0f ? Vec3(eye) / eye.w : Vec3(eye);

  // GL 1.1 equation (2.5): emission + scene ambient + the sum over lights.
  Vec3 c = Vec3(m.emission) + Vec3(m.ambient) * Vec3(s.model.ambient);
  for (const LightSource& l : s.lights) {
    if (!l.enabled) continue;
    Vec3 toLight;
    float attenuation = 1.0f;
    if (l.position.w != 0.0f) {
      toLight = Vec3(l.position) / l.position.w - v;
      const float d = std::sqrt(dot3(toLight, toLight));
      attenuation = 1.0f / (l.constantAttenuation + l.linearAttenuation * d + l.quadraticAttenuation * d * d);
      toLight = d > 0.0f ? toLight / d : toLight;
    } else {
      toLight = normalized(Vec3(l.position));
    }
    float spot = 1.0f;
    if (l.spotCutoff != 180.0f) {
      const float cosAngle = dot3(-toLight, normalized(l.spotDirection));
      const float cosCutoff = static_cast<float>(std::cos(l.spotCutoff * 3.14159265358979323846 / 180.0));
      spot = cosAngle >= cosCutoff ? std::pow(std::max(cosAngle, 0.0f), l.spotExponent) : 0.0f;
    }
    // A light the spot cone or the attenuation zeroes still adds its terms
    // times zero, as Mesa's fixed-function program multiplies LIT's result
    // by the attenuation (ffvertex_prog.c): an overflowed specular power
    // (an unnormalised normal to a high shininess) times zero is NaN, and
    // the clamp below makes the colour white (lighting_zero_scale_nan.gls).
    const float scale = attenuation * spot;
    Vec3 term = Vec3(m.ambient) * Vec3(l.ambient);
    const float nDotL = dot3(n, toLight);
    if (nDotL > 0.0f) {
      term += nDotL * Vec3(m.diffuse) * Vec3(l.diffuse);
      const Vec3 toEye = s.model.localViewer ? normalized(-v) : Vec3(0.0f, 0.0f, 1.0f);
      const float nDotH = dot3(n, normalized(toLight + toEye));
      // max(N.H, 0)^shininess; GL leaves 0^0 open: llvmpipe takes it as 1
      // when no shininess is active in the draw (shininessKeyZero), as 0
      // otherwise.
      float specular = nDotH > 0.0f ? std::pow(nDotH, m.shininess) : (s.shininessKeyZero ? 1.0f : 0.0f);
      const bool attenuated = l.spotCutoff != 180.0f ||
                              (l.position.w != 0.0f && (l.constantAttenuation != 1.0f || l.linearAttenuation != 0.0f ||
                                                        l.quadraticAttenuation != 0.0f));
      if (s.mesaShininess0Attenuated && attenuated) specular = std::pow(nDotL, std::min(nDotL, 128.0f));
      // An overflowed power times a zero colour (0 x infinity) is NaN, and
      // so is the sum: the clamp below decides (lighting_nonfinite.gls).
      if (specular != 0.0f) term += specular * Vec3(m.specular) * Vec3(l.specular);
    }
    c += scale * term;
  }
  // A colour that overflowed (an unnormalised normal to a high power, 0 x
  // infinity, a NaN attenuation or material) is clamped as llvmpipe clamps
  // the lit colour, NaN to 1 in each channel alpha included, and drawn: GL
  // leaves non-finite results open. Measured with mpr conform:
  // tests/hostile/nan_lighting.gls (Mesa's ffvertex_prog makes every lit
  // term NaN times the attenuation; the clamp then gives 1).
  auto clamp01 = [](float v) { return std::isnan(v) ? 1.0f : std::clamp(v, 0.0f, 1.0f); };
  return Vec4(clamp01(c.r), clamp01(c.g), clamp01(c.b), clamp01(m.diffuse.a));
}

}  // namespace mpr
