// draw_ref_shadows for a mirror (1994 Figure 4, Figure 2): the light in front
// of a mirror has a virtual light behind it, which lights only the face's
// light volume.
//
// Hand derivation (16x16, camera at the origin looking down -z, fovy 90):
// the mirror is a 0.5 x 0.5 quad at z = -1 facing -z (towards the wall at
// z = -4, away from the camera, which sees it from behind: culled, and not
// in the depth buffer, so the wall shows through). The light at (0, 0, -2)
// is in front of it; its reflection through z = -1 is the virtual light at
// the origin, so the light volume is the pyramid from the camera's own eye
// through the mirror: on the wall (scale 4) x, y in [-1, 1], window 6..10,
// pixels 6..9 in x and y. face_light_stencil raises every shadow value to
// 193 and counts the volume inverted, so inside it holds SHAD_ZERO = 192.
#include <gtest/gtest.h>

#include <optional>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/stencil_picture.hpp"

namespace mpr {
namespace {

TEST(RefLight, TheMirrorsLightVolumeOnTheWall) {
  const Scene scene = loadSceneText(R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [0, 0, -2]}]
materials: {mirror: {kind: mirror, reflectance: 0.8}}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {name: mirror, primitive: quad, translate: [0, 0, -1], rotate: [180, 0, 1, 0], scale: 0.5, material: mirror}
  - {name: pebble, primitive: box, translate: [3, 3, -3.5], scale: 0.1}
render: {width: 16, height: 16, shadow_recursion_depth: 0}
)", "mirror-light.yaml");
  GLContext gl(16, 16, indigoProfile());
  GLCommandStream stream(gl, false);
  std::optional<Framebuffer> afterVolume;
  std::vector<Rgba8> beforeLight, afterLight;
  stream.onPassEnd([&](const std::string& label) {
    if (label.find("face_light_stencil") != std::string::npos) afterVolume = gl.framebuffer();
    if (label.find("make_all_shadows(CAN'T_INTERSECT") != std::string::npos) beforeLight = gl.framebuffer().colorData();
    if (label.find("lit by the virtual light") != std::string::npos) afterLight = gl.framebuffer().colorData();
  });
  const RenderResult r = renderScene(scene, stream);
  EXPECT_EQ(r.plan.reflectedLights, 1);
  ASSERT_TRUE(afterVolume);
  std::string picture = "\n";
  for (int y = 15; y >= 0; --y) {
    for (int x = 0; x < 16; ++x) picture += (x >= 6 && x <= 9 && y >= 6 && y <= 9) ? "192 " : "193 ";
    picture += "\n";
  }
  EXPECT_TRUE(test::stencilMatches(*afterVolume, 0, 0, picture));
  // The virtual light adds light inside the volume only.
  for (std::size_t i = 0; i < 256; ++i) {
    const int x = static_cast<int>(i % 16), y = static_cast<int>(i / 16);
    const bool inside = x >= 6 && x <= 9 && y >= 6 && y <= 9;
    if (inside) EXPECT_GT(afterLight[i][0], beforeLight[i][0]) << x << "," << y;
    else EXPECT_EQ(afterLight[i], beforeLight[i]) << x << "," << y;
  }
}

// MUST_INTERSECT: a small box between the light and the mirror shadows the
// mirror, and the mirror reflects that shadow into its light volume. The
// camera moves to x = 0.3 (still looking down -z; at the virtual light
// itself every shadow would be seen edge-on), so a wall point x lands at
// window 8 + 2 (x - 0.3). Light volume on the wall x, y in [-1, 1]: window x
// 5.4..9.4, y 6..10: pixels x 5..8, y 6..9. The box's mirror image sits at
// z = -0.5, half-size 0.05; from the virtual light at the origin its shadow
// on the wall has half-size 0.4: window x 6.6..8.2, y 7.2..8.8: pixels x 7,
// y 7..8. The box itself (window x 6.13..6.67, y 7.73..8.27) and its own
// shadow from the virtual light (x 7.13..7.67, y 7.73..8.27) cover no pixel
// centre.
TEST(RefLight, AShadowOnTheMirrorIsReflectedIntoItsLightVolume) {
  const Scene scene = loadSceneText(R"(
camera: {position: [0.3, 0, 0], look_at: [0.3, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [0, 0, -2]}]
materials: {mirror: {kind: mirror, reflectance: 0.8}}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {name: mirror, primitive: quad, translate: [0, 0, -1], rotate: [180, 0, 1, 0], scale: 0.5, material: mirror}
  - {name: blocker, primitive: box, translate: [0, 0, -1.5], scale: 0.1}
render: {width: 16, height: 16, shadow_recursion_depth: 0}
)", "mirror-blocker.yaml");
  GLContext gl(16, 16, indigoProfile());
  GLCommandStream stream(gl, false);
  std::optional<Framebuffer> counted;
  stream.onPassEnd([&](const std::string& label) {
    if (label.find("make_all_shadows(CAN'T_INTERSECT and MUST_INTERSECT") != std::string::npos)
      counted = gl.framebuffer();
  });
  renderScene(scene, stream);
  ASSERT_TRUE(counted);
  std::string picture = "\n";
  for (int y = 15; y >= 0; --y) {
    for (int x = 0; x < 16; ++x) {
      const bool lit = x >= 5 && x <= 8 && y >= 6 && y <= 9;
      const bool shadowed = x == 7 && y >= 7 && y <= 8;
      picture += lit && !shadowed ? "192 " : "193 ";
    }
    picture += "\n";
  }
  EXPECT_TRUE(test::stencilMatches(*counted, 0, 0, picture));
}

}  // namespace
}  // namespace mpr
