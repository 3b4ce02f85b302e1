// A mirror shows what the mirrored camera sees: the reference through a
// perfect mirror (reflectance 1, its own colour black) against the direct
// view, from the camera reflected in the mirror's plane, of the same scene
// without the mirror.
#include "tests/reference/reference_test_support.hpp"

namespace mpr {
namespace {

// Behind the camera (z = 8, facing -z towards the mirror in z = 0): a
// glowing wall, red for world x < 0, green for x > 0, 6 wide and 3 high.
// Emission only, no lights, so its colour does not depend on the view.
const char* kWall = R"(
ambient: [0, 0, 0]
materials:
  red:    {diffuse: [0, 0, 0], emission: [0.9, 0.1, 0.1]}
  green:  {diffuse: [0, 0, 0], emission: [0.1, 0.8, 0.2]}
render: {width: 64, height: 48}
objects:
  - {name: red wall, primitive: quad, translate: [-1.5, 0, 8], rotate: [180, 0, 1, 0], scale: [3, 3, 1], material: red}
  - {name: green wall, primitive: quad, translate: [1.5, 0, 8], rotate: [180, 0, 1, 0], scale: [3, 3, 1], material: green}
)";

TEST(Mirror, ShowsTheMirroredCamerasView) {
  // Real camera at z = 5 looking down -z at the mirror (4 x 4, in z = 0).
  // The mirror's material with the mirror (a material no object has is refused).
  std::string wall = kWall;
  wall.insert(wall.find("render:"), "  mirror: {kind: mirror, diffuse: [0, 0, 0], reflectance: 1}\n");
  const std::string withMirror = wall +
                                 "  - {name: mirror, primitive: quad, scale: [4, 4, 1], material: mirror}\n"
                                 "camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 45, near: 0.1, far: 50}\n";
  // Its image in the plane z = 0: z = -5 looking down +z, no mirror.
  const std::string mirrored =
      std::string(kWall) + "camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 45, near: 0.1, far: 50}\n";
  const ReferenceImage a = test::traceText(withMirror, 1), b = test::traceText(mirrored, 1);
  // The mirrored camera's right is world -x, the real one's +x: pixel x of
  // the mirror's view is pixel 63 - x of the direct one. The wall is 13 away
  // in both; the mirror's edge (ndc 2/5 / tan 22.5 = 0.966) lies outside it.
  // Sample positions differ (each pixel jitters its own way), so compare
  // pixels whose whole neighbourhood in `b` has one colour: there, any
  // sample sees the same surface.
  int compared = 0;
  for (int y = 1; y + 1 < 48; ++y)
    for (int x = 1; x + 1 < 64; ++x) {
      const int bx = 63 - x;
      bool uniform = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          for (int c = 0; c < 3; ++c) uniform &= b.at(bx + dx, y + dy)[c] == b.at(bx, y)[c];
      if (!uniform) continue;
      ++compared;
      for (int c = 0; c < 3; ++c) ASSERT_EQ(a.at(x, y)[c], b.at(bx, y)[c]) << "pixel " << x << "," << y;
    }
  EXPECT_GT(compared, 64 * 48 / 2);
  // By hand: the wall spans |x| < 3, |y| < 1.5 at distance 13: ndc x
  // 3 / 13 / tan(22.5) = 0.557 (window x 14.2 .. 49.8), ndc y 0.279
  // (window y 17.3 .. 30.7). Red (world x < 0) is on the left of the mirror.
  EXPECT_FLOAT_EQ(a.at(20, 24)[0], 0.9f);
  EXPECT_FLOAT_EQ(a.at(44, 24)[1], 0.8f);
  EXPECT_FLOAT_EQ(a.at(10, 24)[0], 0.0f);  // beside the wall: the black background
  EXPECT_FLOAT_EQ(a.at(32, 34)[1], 0.0f);  // above it
}

}  // namespace
}  // namespace mpr
