// The thin lens (camera.aperture, focal_distance): every ray of a pixel
// passes through the point its pinhole ray meets the focal plane, so what
// lies in that plane is as sharp as through a pinhole and what lies off it
// blurs (its image a disc of radius aperture * |1 - f / d| in the focal
// plane, by similar triangles).
#include <cmath>

#include "reference/camera_rays.hpp"
#include "tests/reference/reference_test_support.hpp"

namespace mpr {
namespace {

// Rays of one pixel from four lens points all meet the focal plane (5 along
// the axis) at the pinhole ray's point.
TEST(Lens, RaysOfAPixelMeetInTheFocalPlane) {
  Camera c;
  c.position = {0, 0, 5};
  c.lookAt = {0, 0, 0};
  c.aperture = 0.5f;
  const CameraRays rays(c, 64, 48);
  EXPECT_EQ(rays.focal, 5.0);
  const Ray pin = CameraRays(Camera{c.position, c.lookAt, c.up, c.fovY, c.near, c.far}, 64, 48).through(40.5, 30.5);
  const DVec3 focus = pin.origin + pin.direction * (5.0 / -pin.direction.z);
  for (const DVec2 l : {DVec2(0.1, 0.2), DVec2(0.9, 0.5), DVec2(0.5, 0.99), DVec2(0.3, 0.7)}) {
    const Ray r = rays.through(40.5, 30.5, l);
    EXPECT_NEAR(r.origin.z, 5.0, 1e-12);                     // on the lens, across the axis
    EXPECT_LE(glm::length(DVec2(r.origin.x, r.origin.y)), 0.5 + 1e-12);
    const DVec3 hit = r.origin + r.direction * ((r.origin.z - 0.0) / -r.direction.z);
    EXPECT_NEAR(glm::length(hit - focus), 0.0, 1e-9);
  }
}

// An emitting square in the focal plane keeps the pinhole's bytes on its
// interior; a square 15 behind it (d = 20, f = 5: blur radius 0.3 * 3 = 0.9
// in the focal plane, several pixels) takes values between its colour and
// the black behind at its edges.
TEST(Lens, TheFocalPlaneIsSharpElsewhereBlurs) {
  const std::string scene = R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, near: 0.1, far: 100, aperture: 0.3}
ambient: [0, 0, 0]
materials: {lamp: {diffuse: [0, 0, 0], emission: [1, 1, 1]}}
objects:
  - {name: near square, primitive: quad, translate: [-0.6, 0, 0], scale: 0.8, material: lamp}
  - {name: far square, primitive: quad, translate: [4, 0, -15], scale: 4, material: lamp}
render: {width: 64, height: 48}
)";
  const ReferenceImage lens = test::traceText(scene, 16);
  std::string pinholeScene = scene;
  pinholeScene.replace(pinholeScene.find("aperture: 0.3"), 13, "aperture: 0.0");
  const ReferenceImage pinhole = test::traceText(pinholeScene, 16);
  // The near square spans x -1 .. -0.2 and y -0.4 .. 0.4 at distance 5:
  // half-height 5 tan 20 deg = 1.820, half-width 2.427, so window x 18.8 ..
  // 29.4 and y 18.7 .. 29.3; its interior, x and y 20 .. 28, is 255 both ways.
  for (int y = 20; y <= 28; ++y)
    for (int x = 20; x <= 28; ++x) {
      EXPECT_EQ(test::byteAt(lens, x, y, 0), 255) << x << "," << y;
      EXPECT_EQ(test::byteAt(pinhole, x, y, 0), 255) << x << "," << y;
    }
  int blurred = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 32; x < 64; ++x) {
      const int a = test::byteAt(lens, x, y, 0), p = test::byteAt(pinhole, x, y, 0);
      blurred += a != p && a > 0 && a < 255;
    }
  EXPECT_GT(blurred, 40);
}

}  // namespace
}  // namespace mpr
