// Shadows and light passed on by a mirror, at the pixels similar triangles
// and the mirror image of the light put them.
#include <cmath>

#include "tests/reference/reference_test_support.hpp"

namespace mpr {
namespace {

// Looking straight down from 10 at the floor (y = 0), fov 45, 101 x 101,
// image right = world +x, image up = world -z: pixel (px, py) sees the floor
// at x = ndc(px) * 10 tan(22.5), z = -ndc(py) * 10 tan(22.5).
const char* kFloor = R"(
camera: {position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 45, near: 0.1, far: 50}
ambient: [0.1, 0.1, 0.1]
materials:
  grey:   {diffuse: [0.5, 0.5, 0.5]}
render: {width: 101, height: 101}
objects:
  - {name: floor, primitive: plane, subdivisions: 1, scale: [20, 1, 20], material: grey}
)";

// A blocker at height 1 over x < 0, facing down: the camera sees its back
// (culled, invisible), shadow rays are stopped by either side.
const char* kBlocker =
    "  - {name: blocker, primitive: quad, translate: [-5, 1, 0], rotate: [90, 1, 0, 0], scale: [10, 10, 1], material: grey}\n";

double floorX(int px) { return ((px + 0.5) * 2.0 / 101.0 - 1.0) * 10.0 * std::tan(3.14159265358979 / 8.0); }

// The unshadowed value at floor point x (row 50, z ~ 0) from a light at (1, 3, 0),
// attenuation 1: 0.05 + 0.5 N.L, N.L = 3 / |L - P|.
double litValue(double x) { return 0.05 + 0.5 * 3.0 / std::hypot(1.0 - x, 3.0); }

TEST(Shadow, HardEdgeWhereTheBlockersEdgeProjects) {
  const ReferenceImage im = test::traceText(std::string(kFloor) + kBlocker +
                                                "lights: [{position: [1, 3, 0], color: [1, 1, 1], attenuation: [1, 0, 0]}]\n",
                                            4);
  // The edge (0, 1) seen from the light (1, 3) lands at x = 1 - 1 * 3 / 2 =
  // -0.5: ndc -0.5 / 4.142136 = -0.120711, window x 44.40. Pixels up to 43
  // lie wholly in shadow: ambient only, 0.5 * 0.1 = 0.05, 12.75: 13.
  for (int x = 0; x <= 43; ++x) EXPECT_EQ(test::byteAt(im, x, 50, 0), 13) << "pixel " << x;
  // Pixel 44 is part lit; from 45 on all of it: pixel 45 sees x = -0.410107,
  // N.L = 3 / 3.314865 = 0.905015, 0.05 + 0.452507 = 0.502507: 128.1.
  EXPECT_GT(test::byteAt(im, 44, 50, 0), 13);
  EXPECT_LT(test::byteAt(im, 44, 50, 0), 127);
  EXPECT_NEAR(test::byteAt(im, 45, 50, 0), 128, 1);
  for (int x = 45; x < 101; ++x) EXPECT_NEAR(im.at(x, 50)[0], litValue(floorX(x)), 2e-3) << "pixel " << x;
}

TEST(Shadow, AreaLightPenumbraBySimilarTriangles) {
  const ReferenceImage im = test::traceText(std::string(kFloor) + kBlocker +
                                                "lights: [{position: [1, 3, 0], color: [1, 1, 1], attenuation: [1, 0, 0], radius: 0.5}]\n",
                                            64);
  // The light is a ball of radius 0.5 about (1, 3). The penumbra's ends are
  // the lines through the edge E = (0, 1) tangent to it: |C - E| = sqrt(5),
  // half-angle asin(0.5 / sqrt(5)) = 12.92 deg about the direction -116.57
  // deg, so at -103.65 and -129.49 deg they meet the floor at x = -0.243 and
  // x = -0.824 (penumbra 0.58 wide; the disc facing each point that the
  // reference samples gives -0.245 and -0.821). Pixels are 0.082 wide: one
  // pixel of margin either side.
  for (int x = 0; x < 101; ++x) {
    const double wx = floorX(x);
    const float v = im.at(x, 50)[0];
    if (wx < -0.824 - 0.082) {
      EXPECT_EQ(test::byteAt(im, x, 50, 0), 13) << "umbra, pixel " << x;
    } else if (wx > -0.243 + 0.082) {
      // Wholly lit: N.L and the direction vary over the disc (0.5 across at
      // ~3.2): its points average to within 2% of its centre's value.
      EXPECT_NEAR(v, litValue(wx), 0.02 * litValue(wx)) << "lit, pixel " << x;
    } else if (wx > -0.824 + 0.082 && wx < -0.243 - 0.082) {
      EXPECT_GT(v, 0.05f + 0.01f) << "penumbra, pixel " << x;
      EXPECT_LT(v, 0.98 * litValue(wx)) << "penumbra, pixel " << x;
    }
  }
}

TEST(Shadow, MirrorPassesLightOntoTheHandComputedPatch) {
  // A mirror (1 x 1, reflectance 1) at x = 2 facing -x, y 1..2, z -0.5..0.5.
  // The light (1, 3, 0) has its image at L' = (3, 3, 0). A floor point is lit
  // by L' where the line to L' crosses the mirror: from L' through the
  // mirror's point (2, y, z) the floor is met after s = 3 / (3 - y) of the
  // way, at x = 3 - s, z * s: y = 1 gives x = 1.5, y = 2 gives x = 0; the
  // patch is 0 <= x <= 1.5, |z| <= (3 - x) / 2. There the light adds
  // 0.5 * N.L' with N.L' = 3 / |L' - P| (attenuation 1); e.g. (0.75, 0, 0):
  // 0.05 + 0.5 * 3 / 3.010399 + 0.5 * 3 / 3.75 = 0.05 + 0.498273 + 0.4 = 0.948273.
  std::string floor = kFloor;  // with the mirror's material (a material no object has is refused)
  floor.insert(floor.find("render:"), "  mirror: {kind: mirror, diffuse: [0, 0, 0], reflectance: 1}\n");
  const ReferenceImage im = test::traceText(
      floor +
          "  - {name: mirror, primitive: quad, translate: [2, 1.5, 0], rotate: [-90, 0, 1, 0], material: mirror}\n"
          "lights: [{position: [1, 3, 0], color: [1, 1, 1], attenuation: [1, 0, 0]}]\n",
      4);
  int inside = 0, outside = 0;
  for (int py = 0; py < 101; ++py)
    for (int px = 0; px < 101; ++px) {
      const double x = floorX(px), z = -floorX(py);
      // The mirror is seen edge on beyond x = 2.2 and shadows the floor behind it.
      if (x > 1.9) continue;
      const double edge = std::min({std::fabs(x), std::fabs(x - 1.5), std::fabs(std::fabs(z) - (3.0 - x) / 2.0)});
      if (edge < 0.15) continue;  // within two pixels of the patch's edge
      const bool patch = x > 0.0 && x < 1.5 && std::fabs(z) < (3.0 - x) / 2.0;
      double expected = 0.05 + 0.5 * 3.0 / std::sqrt((1 - x) * (1 - x) + 9 + z * z);
      if (patch) expected += 0.5 * 3.0 / std::sqrt((3 - x) * (3 - x) + 9 + z * z);
      ++(patch ? inside : outside);
      ASSERT_NEAR(im.at(px, py)[0], expected, 3e-3) << "pixel " << px << "," << py << (patch ? " (patch)" : "");
    }
  EXPECT_GT(inside, 200);
  EXPECT_GT(outside, 2000);
  EXPECT_NEAR(test::quantise(0.948273), 242, 0);
}

}  // namespace
}  // namespace mpr
