// A refracting plane bends the view by Snell's law: a small glowing ball
// behind it is seen where the refracted ray, not the straight line, meets it.
#include "tests/reference/reference_test_support.hpp"

namespace mpr {
namespace {

// Camera 5 in front of the glass (z = 0, facing the camera, ior 1.5, all
// transmitted, its own colour black), fov 90: pixel x sees the glass at
// x = 5 * ndc. The ball (radius 0.08, emission 1) is 2 behind the glass.
//
// By hand, for pixel 160 of 201: ndc = 321 / 201 - 1 = 0.597015, the ray
// meets the glass at x_s = 2.985075, theta_1 = atan(x_s / 5) = 30.838 deg,
// sin(theta_1) = 0.512610; from the front the ray passes from air into the
// glass (1994's change of medium): sin(theta_2) = 0.512610 / 1.5 = 0.341740,
// tan(theta_2) = 0.363633, and 2 further it is at x = 2.985075 + 2 *
// 0.363633 = 3.712340. The ball is put there; seen straight (no glass) it
// would be at ndc 3.712340 / 7 = 0.530334, window x 153.8: pixel 153.
const char* kGlass = R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 90, near: 0.1, far: 50}
ambient: [0, 0, 0]
materials:
  glow:  {diffuse: [0, 0, 0], emission: [1, 1, 1]}
render: {width: 201, height: 201}
objects:
  - {name: ball, primitive: sphere, subdivisions: 24, translate: [3.712340, 0, -2], scale: 0.08, material: glow}
)";

// The brightness-weighted mean window x of row y (pixel x's centre is x + 0.5).
double centroidOfRow(const ReferenceImage& im, int y) {
  double sum = 0.0, weighted = 0.0;
  for (int x = 0; x < im.width; ++x) sum += im.at(x, y)[0], weighted += im.at(x, y)[0] * (x + 0.5);
  return sum > 0.0 ? weighted / sum : -1.0;
}

TEST(Refraction, PointBehindThePlaneIsWhereSnellPutsIt) {
  // The glass's material with the glass (a material no object has is refused).
  std::string glassScene = kGlass;
  glassScene.insert(glassScene.find("render:"), "  glass: {kind: refractive, diffuse: [0, 0, 0], ior: 1.5, transmittance: 1}\n");
  const std::string withGlass = glassScene + "  - {name: glass, primitive: quad, scale: [40, 40, 1], material: glass}\n";
  const ReferenceImage glass = test::traceText(withGlass, 16), straight = test::traceText(kGlass, 16);
  // The ball lies in the plane y = 0, the plane of incidence: row 100. Its
  // image is about three pixels wide (0.16 across at ~7); its centre is seen
  // through window x 160.5 (pixel 160's centre). The glass squeezes the
  // image a little unevenly, so allow a third of a pixel.
  EXPECT_NEAR(centroidOfRow(glass, 100), 160.5, 0.35);
  EXPECT_GT(glass.at(160, 100)[0], 0.99f);
  EXPECT_NEAR(centroidOfRow(straight, 100), 153.8, 0.35);
  // Nothing is seen where the straight line would put it.
  EXPECT_EQ(glass.at(153, 100)[0], 0.0f);
  EXPECT_EQ(glass.at(154, 100)[0], 0.0f);
}

}  // namespace
}  // namespace mpr
