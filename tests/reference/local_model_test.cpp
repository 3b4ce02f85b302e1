// The local model against GL 1.1 §2.13's lighting equation evaluated by
// hand: a diffuse and specular wall seen head-on under one point light.
#include <cmath>

#include "reference/shading.hpp"
#include "tests/reference/reference_test_support.hpp"

namespace mpr {
namespace {

// Camera 5 in front of a wall in z = 0, fov 90 (tan 45 = 1: window pixel x
// sees the wall at x = 5 * ndc), the light 2 in front of the wall.
const char* kWall = R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 90, near: 0.1, far: 50}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [0, 0, 2], color: [1, 1, 1], attenuation: [1, 0.5, 0.25]}]
materials:
  grey: {diffuse: [0.5, 0.5, 0.5], specular: [0.2, 0.2, 0.2], shininess: 10}
objects:
  - {name: wall, primitive: quad, scale: [20, 20, 1], material: grey}
render: {width: 101, height: 101}
)";

TEST(LocalModel, CentrePixelIsTheGlFormula) {
  const ReferenceImage im = test::traceText(kWall, 4);
  // Pixel (50, 50) is centred on the axis: P = (0, 0, 0), N = L = V = +z,
  // d = 2, attenuation 1 / (1 + 0.5 * 2 + 0.25 * 4) = 1/3, N.L = N.H = 1:
  //   0.5 * 0.1 + (0.5 * 1 + 0.2 * 1^10) / 3 = 0.05 + 0.233333 = 0.283333,
  // 72.25 of 255: 72. The samples stay within the pixel, 0.05 from the axis,
  // where d^2 grows by 0.0025: the value moves by ~2e-4, far from a rounding
  // boundary, so the byte is exact.
  EXPECT_NEAR(im.at(50, 50)[0], 0.283333, 5e-4);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(test::byteAt(im, 50, 50, c), 72);
}

TEST(LocalModel, OffAxisPixelIsTheGlFormulaWithTheTrueViewer) {
  const ReferenceImage im = test::traceText(kWall, 16);
  // Pixel (80, 50): ndc x = 161 / 101 - 1 = 0.594059, P = (2.970297, 0, 0).
  //   L - P = (-2.970297, 0, 2), d = 3.580875, N.L = 2 / d = 0.558523,
  //   attenuation 1 / (1 + 1.790438 + 3.205666) = 0.166775.
  //   V = (-2.970297, 0, 5) / 5.815726 = (-0.510736, 0, 0.859741) (the true
  //   viewer; GL's infinite viewer would take (0, 0, 1)), L = (-0.829489, 0,
  //   0.558523), H = (L + V) / |L + V|, N.H = 1.418264 / 1.951327 = 0.726821,
  //   N.H^10 = 0.041136.
  //   0.05 + 0.166775 * (0.5 * 0.558523 + 0.2 * 0.041136) = 0.097946: 24.98 of 255.
  // The 16 samples spread over the pixel (0.099 wide on the wall), where the
  // value changes by about 1e-3 from side to side: the mean stays within
  // 5e-4 of the centre's value, and the byte within one of 25.
  EXPECT_NEAR(im.at(80, 50)[0], 0.097946, 5e-4);
  EXPECT_NEAR(test::byteAt(im, 80, 50, 1), 25, 1);
}

TEST(LocalModel, WardLobeIsEquationFive) {
  SceneMaterial m;
  m.diffuse = Vec3(0.0f);
  m.roughness = 0.2f;
  m.wardSpecular = Vec3(0.1f);
  // N = +z, L = V = 45 degrees from it in the xz plane on either side:
  // H = N, delta = 0, cos(theta_i) = cos(theta_r) = 0.707107:
  //   rho_s cos(theta_i) / (4 pi alpha^2 sqrt(cos_i cos_r)) = 0.1 * 0.707107 / (4 pi 0.04 * 0.707107)
  //   = 0.1 / 0.502655 = 0.198944.
  const double s = std::sqrt(0.5);
  const DVec3 c = lightTerm(m, ShadingModel::Physical, {0, 0, 1}, {-s, 0, s}, {s, 0, s}, DVec3(1.0));
  EXPECT_NEAR(c.x, 0.1 / (4.0 * 3.14159265358979 * 0.2f * 0.2f), 1e-7);
  EXPECT_NEAR(c.x, 0.198944, 1e-5);
}

}  // namespace
}  // namespace mpr
