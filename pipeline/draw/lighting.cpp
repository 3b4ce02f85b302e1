#include "pipeline/draw/lighting.hpp"

#include <algorithm>
#include <cmath>

#include "raster/llvmpipe_math.hpp"
#include "pipeline/draw/mesa_matrix_inverse.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

float dot3(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

float dp3(const Vec3& a, const Vec3& b) { return llvmpipeDot3(a, b); }  // the program's DP3

// emit_normalize_vec3: DP3, RSQ (a square root and a division), MUL.
Vec3 programNormalized(const Vec3& v) { return v * (1.0f / std::sqrt(dp3(v, v))); }

// Mesa's NORMALIZE_3FV (CPU-side state) and the program's DP3, RSQ, MUL
// (emit_normalize_vec3; llvmpipe's RSQ is a square root and a division):
// both v * (1 / sqrt(v.v)), the zero vector kept.
Vec3 normalizedByReciprocal(const Vec3& v) {
  const float lengthSquared = dot3(v, v);
  if (!(lengthSquared != 0.0f)) return v;
  return v * (1.0f / std::sqrt(lengthSquared));
}

// (a * b) + c per channel, unfused: a MAD of Mesa's program as llvmpipe runs
// it (nir lowers ffma to a multiply and an add).
Vec3 mad(float a, const Vec3& b, const Vec3& c) { return a * b + c; }

}  // namespace

bool mesaLightsInObjectSpace(const LightingState& s, unsigned modelviewFlags) {
  // _mesa_update_tnl_spaces: eye coordinates are needed for a positional
  // light, a local viewer, or a modelview whose Mesa flags are not only
  // rotation and translation (_math_matrix_is_length_preserving). A spot
  // light needs them too (measured: lighting seed 1329, a directional spot
  // light, lighting_spot_eye_space.gls).
  if (s.model.localViewer) return false;
  if ((modelviewFlags & mesa_matrix::kGeometry & ~(mesa_matrix::kRotation | mesa_matrix::kTranslation)) != 0)
    return false;
  for (const LightSource& l : s.lights)
    if (l.enabled && (l.position.w != 0.0f || l.spotCutoff != 180.0f)) return false;
  return true;
}

void toObjectSpace(LightingState& s, const Mat4& modelview, const Mat4& inverse) {
  s.objectSpace = true;
  // TRANSFORM_NORMAL(_EyeZDir, (0, 0, 1), m): the third entry of each column.
  s.eyeZDirection = Vec3(modelview[0][2], modelview[1][2], modelview[2][2]);
  // TRANSFORM_POINT(_Position, inv, EyePosition); no light here is a spot
  // light (mesaLightsInObjectSpace), so no spot direction moves.
  for (LightSource& l : s.lights)
    if (l.enabled) l.position = mesaTransformPoint(inverse, l.position);
}

// Mesa's fixed-function vertex program (ffvertex_prog.c build_lighting and
// calculate_light_attenuation, Mesa 22.3), step for step in its order and
// single precision, so that a lit colour is llvmpipe's to the last bit:
//  - the colour starts as the scene colour, model ambient * ambient +
//    emission (STATE_LIGHTMODEL_SCENECOLOR);
//  - per light: the light products light * material (STATE_LIGHTPROD); a
//    positional light's VP = P - V, 1/d = RSQ(VP.VP), VP *= 1/d; a
//    directional one's VP its position normalised (NORMALIZE_3FV);
//  - the spot factor (-VP.s >= cos cutoff) * |-VP.s|^exponent, s the
//    normalised spot direction; the distance factor 1 / (k0 (1/d) d + k1 d +
//    k2 d d) (RCP, MUL, DP3, RCP; d and d d as below);
//  - LIT: (1, max(N.VP, 0), N.VP > 0 ? max(N.H, 0)^shininess : 0, 1), times
//    the attenuation when there is one; the colour then col += lit.x *
//    ambient product (with attenuation) or col = ambient product + col
//    (without), col = lit.y * diffuse product + col, col = lit.z *
//    specular product + col, each MAD unfused.
MPR_CPU_CLONES Vec4 lightVertex(const LightingState& s, const Vec4& eye, const Vec3& normalIn, bool back) {
  const Material& m = s.material[back ? 1 : 0];
  const Vec3 n = back ? -normalIn : normalIn;
  const Vec3 v = eye.w != 0.0f ? Vec3(eye) / eye.w : Vec3(eye);
  const Vec3 zAxis = s.eyeZDirection;

  Vec3 c = Vec3(s.model.ambient) * Vec3(m.ambient) + Vec3(m.emission);
  for (const LightSource& l : s.lights) {
    if (!l.enabled) continue;
    const bool positional = l.position.w != 0.0f;
    Vec3 toLight;
    float inverseDistance = 0.0f, squaredDistance = 0.0f;
    if (positional) {
      toLight = Vec3(l.position) / l.position.w - v;
      squaredDistance = dp3(toLight, toLight);
      inverseDistance = 1.0f / std::sqrt(squaredDistance);
      toLight = toLight * inverseDistance;
    } else {
      toLight = normalizedByReciprocal(Vec3(l.position));
    }
    // calculate_light_attenuation: none (the key's light_attenuated and
    // light_spotcutoff_is_180) leaves the LIT result unscaled.
    const bool spotLight = l.spotCutoff != 180.0f;
    const bool distanceAttenuated = positional && (l.constantAttenuation != 1.0f || l.linearAttenuation != 0.0f ||
                                                   l.quadraticAttenuation != 0.0f);
    const bool attenuated = spotLight || distanceAttenuated;
    float attenuation = 1.0f;
    if (spotLight) {
      const Vec3 direction = normalizedByReciprocal(l.spotDirection);
      const float cosCutoff = static_cast<float>(std::cos(l.spotCutoff * 3.14159265358979323846 / 180.0));
      const float cosAngle = dp3(-toLight, direction);
      // Mesa's SLT is strict; GL 1.1 keeps a vertex on the cone's edge
      // inside (the angle must exceed the cutoff), and GL wins where exact.
      const float inside = cosAngle >= cosCutoff ? 1.0f : 0.0f;
      attenuation = inside * llvmpipePow(std::fabs(cosAngle), l.spotExponent);  // POW
    }
    if (distanceAttenuated) {
      // RCP, MUL, DP3 as llvmpipe runs them after NIR's algebraic pass: the
      // RCP of the RSQ a square root (frcp(frsq(a)) -> fsqrt(a)), d d the
      // squared distance itself (fsqrt(a) * fsqrt(a) -> a), the DP3 summed
      // from the last channel as every DP3 of the program. Measured: of the
      // orders and forms tried, only this one gives both the periscope's and
      // the bathroom's whole renders llvmpipe's bytes
      // (lighting_attenuation_dp3.gls).
      const float d = std::sqrt(squaredDistance);
      const float one = inverseDistance * d;
      const float factor =
          1.0f / llvmpipeDot3(Vec3(l.constantAttenuation, l.linearAttenuation, l.quadraticAttenuation),
                              Vec3(one, d, squaredDistance));
      attenuation = spotLight ? factor * attenuation : factor;
    }
    const float nDotL = dp3(n, toLight);
    // LIT's y and z (emit_degenerate_lit without a shininess: max(N.L, 0)
    // and N.L > 0; the same values).
    const float litY = std::max(nDotL, 0.0f);
    float litZ = nDotL > 0.0f ? 1.0f : 0.0f;
    if (nDotL > 0.0f && !s.shininessKeyZero) {
      Vec3 half;
      if (s.model.localViewer) half = programNormalized(toLight - programNormalized(v));
      else if (!positional) half = normalizedByReciprocal(normalizedByReciprocal(Vec3(l.position)) + zAxis);  // STATE_LIGHT_HALF_VECTOR
      else half = programNormalized(toLight + zAxis);
      const float nDotH = dp3(n, half);
      // max(N.H, 0)^shininess; GL leaves 0^0 open: llvmpipe takes it as 0
      // here (a shininess is active in the draw: shininessKeyZero false).
      litZ = nDotH > 0.0f ? llvmpipePow(nDotH, std::clamp(m.shininess, -128.0f, 128.0f)) : 0.0f;
    }
    // With no shininess active and an attenuated light, Mesa's dot products
    // are all N.VP and LIT takes (N.VP)^(N.VP) (a departure from GL's 1,
    // emulated only for mpr conform: shininess0_attenuated).
    if (s.mesaShininess0Attenuated && attenuated && nDotL > 0.0f && s.shininessKeyZero)
      litZ = llvmpipePow(nDotL, std::min(nDotL, 128.0f));
    const Vec3 ambient = Vec3(l.ambient) * Vec3(m.ambient), diffuse = Vec3(l.diffuse) * Vec3(m.diffuse),
               specular = Vec3(l.specular) * Vec3(m.specular);
    // A light the spot cone or the attenuation zeroes still adds its terms
    // times zero: an overflowed specular power (an unnormalised normal to a
    // high shininess) times zero is NaN, and the clamp below makes the
    // colour white (lighting_zero_scale_nan.gls).
    if (attenuated) {
      c = mad(attenuation, ambient, c);
      c = mad(litY * attenuation, diffuse, c);
      c = mad(litZ * attenuation, specular, c);
    } else {
      c = ambient + c;
      c = mad(litY, diffuse, c);
      c = mad(litZ, specular, c);
    }
  }
  // A colour that overflowed (an unnormalised normal to a high power, 0 x
  // infinity, a NaN attenuation or material) is clamped as llvmpipe clamps
  // the lit colour, NaN to 1 in each channel alpha included, and drawn: GL
  // leaves non-finite results open. Measured with mpr conform:
  // tests/hostile/nan_lighting.gls (Mesa's ffvertex_prog makes every lit
  // term NaN times the attenuation; the clamp then gives 1).
  auto clamp01 = [](float x) { return std::isnan(x) ? 1.0f : std::clamp(x, 0.0f, 1.0f); };
  return Vec4(clamp01(c.r), clamp01(c.g), clamp01(c.b), clamp01(m.diffuse.a));
}

}  // namespace mpr
