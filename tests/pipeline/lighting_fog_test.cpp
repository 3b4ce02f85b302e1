// Fixed-function lighting and fog factors at hand-derived points. Tolerances
// of 1e-6 are single-precision rounding of the few operations involved.
#include <gtest/gtest.h>

#include <cmath>

#include "raster/fog.hpp"
#include "pipeline/draw/lighting.hpp"

namespace mpr {
namespace {

constexpr float kTol = 1e-6f;

LightingState oneLight() {
  LightingState s;
  s.model.ambient = Vec4(0, 0, 0, 1);
  s.lights[0].enabled = true;
  s.lights[0].diffuse = Vec4(1, 1, 1, 1);
  s.lights[0].specular = Vec4(0, 0, 0, 1);
  s.material[0].ambient = Vec4(0, 0, 0, 1);
  s.material[0].diffuse = Vec4(1, 0.5f, 0.25f, 0.75f);
  return s;
}

TEST(Lighting, DiffuseFollowsTheCosine) {
  LightingState s = oneLight();
  s.lights[0].position = Vec4(0, 0, 1, 0);  // directional, along +z
  // Normal at 60 degrees from the light: cos = 0.5.
  const Vec3 n(std::sqrt(3.0f) / 2.0f, 0.0f, 0.5f);
  const Vec4 c = lightVertex(s, Vec4(0, 0, 0, 1), n, false);
  EXPECT_NEAR(c.r, 0.5f, kTol);
  EXPECT_NEAR(c.g, 0.25f, kTol);
  EXPECT_NEAR(c.b, 0.125f, kTol);
  EXPECT_EQ(c.a, 0.75f);  // the diffuse alpha
  // Facing away: no diffuse at all.
  EXPECT_EQ(lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, -1), false), Vec4(0, 0, 0, 0.75f));
}

TEST(Lighting, EmissionAndAmbientAndClamping) {
  LightingState s = oneLight();
  s.lights[0].enabled = false;
  s.material[0].emission = Vec4(0.1f, 0.2f, 0.3f, 1);
  s.material[0].ambient = Vec4(0.5f, 0.5f, 0.5f, 1);
  s.model.ambient = Vec4(0.2f, 0.4f, 4.0f, 1);
  const Vec4 c = lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, 1), false);
  EXPECT_NEAR(c.r, 0.2f, kTol);  // 0.1 + 0.5 * 0.2
  EXPECT_NEAR(c.g, 0.4f, kTol);  // 0.2 + 0.5 * 0.4
  EXPECT_EQ(c.b, 1.0f);          // 0.3 + 2.0, clamped
}

TEST(Lighting, SpecularInfiniteAndLocalViewer) {
  LightingState s = oneLight();
  s.material[0].diffuse = Vec4(0, 0, 0, 1);
  s.material[0].specular = Vec4(1, 1, 1, 1);
  s.material[0].shininess = 2.0f;
  s.shininessKeyZero = false;  // a shininess is active (GLContext decides it per draw)
  s.lights[0].specular = Vec4(1, 1, 1, 1);
  s.lights[0].position = Vec4(0, 0, 1, 0);
  // Infinite viewer: h = normalize(L + (0,0,1)) = (0,0,1). With n at 60
  // degrees, n.h = 0.5 and 0.5^2 = 0.25.
  const Vec3 n(std::sqrt(3.0f) / 2.0f, 0.0f, 0.5f);
  EXPECT_NEAR(lightVertex(s, Vec4(4, 0, -4, 1), n, false).r, 0.25f, kTol);
  // Local viewer at the origin, vertex at (4, 0, -4): to eye = (-1, 0, 1)/sqrt2,
  // h = normalize((0,0,1) + (-1,0,1)/sqrt2); n = (0,0,1): n.h = cos(22.5 deg),
  // squared = (1 + cos 45) / 2 = 0.853553.
  s.model.localViewer = true;
  EXPECT_NEAR(lightVertex(s, Vec4(4, 0, -4, 1), Vec3(0, 0, 1), false).r, 0.8535534f, kTol);
}

TEST(Lighting, AttenuationAndSpot) {
  LightingState s = oneLight();
  s.lights[0].position = Vec4(0, 0, 3, 1);  // 3 units above the vertex
  s.lights[0].linearAttenuation = 1.0f;     // 1 / (1 + 3) = 0.25
  EXPECT_NEAR(lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, 1), false).r, 0.25f, kTol);
  s.lights[0].linearAttenuation = 0.0f;
  s.lights[0].spotDirection = Vec3(0, 0, -1);
  s.lights[0].spotCutoff = 30.0f;
  s.lights[0].spotExponent = 2.0f;
  // Straight below the spot: cos 0 = 1, inside the cone.
  EXPECT_NEAR(lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, 1), false).r, 1.0f, kTol);
  // At (3, 0, 0): 45 degrees off axis, outside a 30 degree cone.
  EXPECT_EQ(lightVertex(s, Vec4(3, 0, 0, 1), Vec3(0, 0, 1), false).r, 0.0f);
  // At (sqrt3, 0, 0): 30 degrees off the axis; on the cone edge cos30^2 = 0.75,
  // and n.L = cos 30 as well: 0.75 * 0.866 = 0.6495.
  const float x = std::sqrt(3.0f);
  EXPECT_NEAR(lightVertex(s, Vec4(x, 0, 0, 1), Vec3(0, 0, 1), false).r, 0.75f * std::sqrt(3.0f) / 2.0f, 2e-6f);
}

TEST(Lighting, BackMaterialUsesTheNegatedNormal) {
  LightingState s = oneLight();
  s.lights[0].position = Vec4(0, 0, 1, 0);
  s.material[1] = s.material[0];
  s.material[1].diffuse = Vec4(0, 1, 0, 1);
  EXPECT_EQ(lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, -1), true), Vec4(0, 1, 0, 1));
  EXPECT_EQ(lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, -1), false), Vec4(0, 0, 0, 0.75f));
}

TEST(Fog, LinearFactors) {
  FogState f;
  f.mode = FogMode::Linear;
  f.start = 2.0f;
  f.end = 10.0f;
  EXPECT_EQ(fogFactor(f, 2.0f), 1.0f);
  EXPECT_EQ(fogFactor(f, 10.0f), 0.0f);
  EXPECT_EQ(fogFactor(f, 6.0f), 0.5f);
  EXPECT_EQ(fogFactor(f, 12.0f), 0.0f);  // clamped
  EXPECT_EQ(fogFactor(f, 0.0f), 1.0f);   // clamped
  f.end = f.start;  // start = end, which GL leaves open: llvmpipe's clamp(c - end), not a step
  EXPECT_EQ(fogFactor(f, 1.0f), 0.0f);
  EXPECT_EQ(fogFactor(f, 2.5f), 0.5f);
  EXPECT_EQ(fogFactor(f, 3.0f), 1.0f);
}

TEST(Fog, ExponentialFactors) {
  FogState f;
  f.mode = FogMode::Exp;
  f.density = 0.5f;
  EXPECT_NEAR(fogFactor(f, 2.0f * std::log(2.0f)), 0.5f, kTol);  // e^(-0.5 * 2 ln 2) = 1/2
  EXPECT_EQ(fogFactor(f, 0.0f), 1.0f);
  f.mode = FogMode::Exp2;
  EXPECT_NEAR(fogFactor(f, 2.0f * std::sqrt(std::log(2.0f))), 0.5f, kTol);  // e^-(ln 2)
}

TEST(Fog, ApplyBlendsRgbAndKeepsAlpha) {
  FogState f;
  f.color = Vec4(0, 1, 0.5f, 0);
  const Vec4 c = applyFog(f, 0.25f, Vec4(1, 0, 0.5f, 0.8f));
  EXPECT_EQ(c, Vec4(0.25f, 0.75f, 0.5f, 0.8f));
}

}  // namespace
}  // namespace mpr
