// draw_ref_shadows (1994 Figure 4, Figure 2): the light in front
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

#include <cmath>
#include <optional>

#include "algorithms/ref_light.hpp"
#include "algorithms/render_plan.hpp"
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
    if (label.find("lit by the virtual light") != std::string::npos && afterLight.empty()) afterLight = gl.framebuffer().colorData();
  });
  const RenderResult r = renderScene(scene, stream);
  EXPECT_EQ(r.plan.reflectedLights, 1);
  ASSERT_TRUE(afterVolume);
  EXPECT_TRUE(test::stencilMatches(*afterVolume, 0, 0, test::stencilPictureOf(16, 16, [](int x, int y) {
    return x >= 6 && x <= 9 && y >= 6 && y <= 9 ? 192 : 193;
  })));
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
  EXPECT_TRUE(test::stencilMatches(*counted, 0, 0, test::stencilPictureOf(16, 16, [](int x, int y) {
    const bool lit = x >= 5 && x <= 8 && y >= 6 && y <= 9;
    const bool shadowed = x == 7 && y >= 7 && y <= 8;
    return lit && !shadowed ? 192 : 193;
  })));
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

// A glass pane bends its light and the shadows in it (1994 "Refractive
// shadows", Figure 2; change-of-medium model). Hand derivation (16x16,
// camera at the origin looking down -z, fovy 90, wall at z = -4 filling the
// view: a wall point (X, Y) lands at window (8 + 2X, 8 + 2Y)):
// - The pane: 1.2 x 1.2 at z = -2 facing +z, ior 1.5. The light at
//   C + 3.5 (-0.6, 0, 0.8) = (-2.1, 0, 0.8): incidence at the centre C
//   sin 0.6, refracted sin 0.4. The virtual light is the light's paraxial
//   image on the refracted ray, at 1.5 times its distance:
//   C - 5.25 (0.4, 0, -sqrt(0.84)) = (-2.1, 0, 2.8117).
// - Light volume (from the virtual light through the pane) on the wall:
//   window x 8.05..11.45, y 6.30..9.70: pixels x 8..10, y 6..9.
// - The pane's own shadow from the real light (draw_all_shadows):
//   window x 8.94..13.06, y 5.94..10.06: pixels x 9..12, y 6..9.
// - A blocker (0.16 cube at (-1.26, 0, -0.32), on the ray from the light to
//   C, off screen) shadows the pane: MUST_INTERSECT. Carried through the
//   face (P + (L' - L) dist(P) / dist(L)), its shadow from the virtual light
//   is the hexagon x 8.82..10.81, y 7.39..8.61: pixels x 9..10, y 7..8 — one
//   pixel left of its straight shadow from the real light (x 9.88..12.29:
//   pixels 10..11, y 7..8). Every pixel centre is at least 0.05 pixel (a
//   dozen snapping steps) from every edge.
TEST(RefLight, AGlassPaneBendsItsLightVolumeAndTheShadowInIt) {
  const Scene scene = loadSceneText(R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [-2.1, 0, 0.8]}]
materials: {glass: {kind: refractive, ior: 1.5, transmittance: 0.8}}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {name: pane, primitive: quad, translate: [0, 0, -2], scale: 1.2, material: glass}
  - {name: blocker, primitive: box, translate: [-1.26, 0, -0.32], scale: 0.16}
render: {width: 16, height: 16, shadow_recursion_depth: 0}
)", "glass-light.yaml");
  GLContext gl(16, 16, indigoProfile());
  GLCommandStream stream(gl, false);
  std::optional<Framebuffer> afterVolume, afterRefShadows, afterDirectShadows;
  std::vector<Rgba8> beforeLight, afterLight;
  stream.onPassEnd([&](const std::string& label) {
    // The first of each: the level-1 view through the pane draws the
    // virtual light again, unshadowed (past shadow_recursion_depth 0).
    if (label.find("face_light_stencil") != std::string::npos && !afterVolume) afterVolume = gl.framebuffer();
    if (label.find("make_all_shadows(CAN'T_INTERSECT") != std::string::npos) {
      afterRefShadows = gl.framebuffer();
      beforeLight = gl.framebuffer().colorData();
    }
    if (label.find("lit by the virtual light") != std::string::npos && afterLight.empty()) afterLight = gl.framebuffer().colorData();
    if (label.find("make_all_shadows(ALWAYS)") != std::string::npos) afterDirectShadows = gl.framebuffer();
  });
  const RenderResult r = renderScene(scene, stream);
  EXPECT_EQ(r.plan.reflectedLights, 1);
  ASSERT_TRUE(afterVolume && afterRefShadows && afterDirectShadows);
  auto picture = [](auto value) { return test::stencilPictureOf(16, 16, value); };
  auto inVolume = [](int x, int y) { return x >= 8 && x <= 10 && y >= 6 && y <= 9; };
  auto inBentShadow = [](int x, int y) { return x >= 9 && x <= 10 && y >= 7 && y <= 8; };
  EXPECT_TRUE(test::stencilMatches(*afterVolume, 0, 0, picture([&](int x, int y) { return inVolume(x, y) ? 192 : 193; })));
  EXPECT_TRUE(test::stencilMatches(*afterRefShadows, 0, 0, picture([&](int x, int y) {
    return inVolume(x, y) && !inBentShadow(x, y) ? 192 : 193;
  })));
  // draw_all_shadows: the pane's shadow and the blocker's straight one.
  EXPECT_TRUE(test::stencilMatches(*afterDirectShadows, 0, 0, picture([](int x, int y) {
    const bool pane = x >= 9 && x <= 12 && y >= 6 && y <= 9;
    const bool blocker = x >= 10 && x <= 11 && y >= 7 && y <= 8;
    return 192 + pane + blocker;
  })));
  // The refracted light is added inside the volume, outside the bent shadow.
  ASSERT_EQ(afterLight.size(), 256u);
  for (std::size_t i = 0; i < 256; ++i) {
    const int x = static_cast<int>(i % 16), y = static_cast<int>(i / 16);
    if (inVolume(x, y) && !inBentShadow(x, y)) EXPECT_GT(afterLight[i][0], beforeLight[i][0]) << x << "," << y;
    else EXPECT_EQ(afterLight[i], beforeLight[i]) << x << "," << y;
  }
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

RefFace paneAtOrigin(MaterialKind kind, double ior) {
  RefFace f;
  f.kind = kind;
  f.ior = ior;
  f.polygon = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  f.normal = DVec3(0, 0, 1);
  f.offset = 0.0;
  f.centre = DVec3(0.0);
  return f;
}

// ref_light: the mirror reflects; the refracting face moves the light onto
// the refracted ray through its centre (Snell's law there), where that ray
// meets the perpendicular from the light to the face's plane: its distance
// times n_other / n_light (the paraxial image); no light passes a mirror from behind, a face from its own plane,
// or a refracting face past the critical angle; index 1 is the light itself.
TEST(RefLight, VirtualLightPositions) {
  const RefFace mirror = paneAtOrigin(MaterialKind::Mirror, 1.0);
  EXPECT_EQ(refLightPosition(mirror, DVec3(1, 2, 3)), DVec3(1, 2, -3));
  EXPECT_FALSE(refLightPosition(mirror, DVec3(1, 2, -3)));
  EXPECT_FALSE(refLightPosition(mirror, DVec3(1, 2, 0)));

  const RefFace glass = paneAtOrigin(MaterialKind::Refractive, 1.5);
  const DVec3 light(-0.6 * 2.0, 0.0, 0.8 * 2.0);  // incidence sin 0.6 at distance 2
  const auto ref = refLightPosition(glass, light);
  ASSERT_TRUE(ref);
  EXPECT_NEAR(glm::length(*ref), 3.0, 1e-15);  // 2 * 1.5 / 1
  EXPECT_NEAR(ref->x, light.x, 1e-15);           // on the light's perpendicular to the face
  EXPECT_EQ(ref->y, 0.0);
  // Seen from the virtual light, the centre lies along the refracted ray: sin 0.4.
  const DVec3 t = glm::normalize(DVec3(0.0) - *ref);
  EXPECT_NEAR(t.x, 0.4, 1e-15);
  EXPECT_NEAR(t.z, -std::sqrt(0.84), 1e-15);
  EXPECT_EQ(refLightPosition(paneAtOrigin(MaterialKind::Refractive, 1.0), light), light);
  EXPECT_FALSE(refLightPosition(glass, DVec3(1, 0, 0)));
  // From inside the glass (behind the face), the critical angle asin(1/1.5):
  // just below it light passes, just above it none does.
  const double critical = std::asin(1.0 / 1.5);
  for (const double delta : {-1e-6, 1e-6}) {
    const double a = critical + delta;
    const auto r = refLightPosition(glass, DVec3(-std::sin(a), 0.0, -std::cos(a)));
    EXPECT_EQ(r.has_value(), delta < 0.0) << delta;
    if (r) {
      EXPECT_TRUE(std::isfinite(r->x) && std::isfinite(r->z));
    }
  }
}

// A mirror and a light with nothing casting a shadow: the mirror still lights
// the room, so the plan keeps the shadow passes (its light volume is a
// stencil count); with shadows switched off it does not.
TEST(RefLight, AMirrorLightsTheRoomWithoutAnyCaster) {
  const std::string text = R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [0, 0, -2]}]
materials: {mirror: {kind: mirror, reflectance: 0.8}}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {name: mirror, primitive: quad, translate: [0, 0, -1], rotate: [180, 0, 1, 0], scale: 0.5, material: mirror, casts_shadows: false}
)";
  const RenderPlan on = planRender(loadSceneText(text + "render: {width: 16, height: 16}\n", "m.yaml"));
  EXPECT_EQ(on.shadowCasters, 0);
  EXPECT_TRUE(on.shadows);
  EXPECT_EQ(on.reflectedLights, 1);
  const RenderPlan off = planRender(loadSceneText(text + "render: {width: 16, height: 16, shadows: false}\n", "m.yaml"));
  // Without shadows the mirror still lights the room, through its light
  // volume alone (issue 43: its light was lost).
  EXPECT_FALSE(off.shadows);
  EXPECT_EQ(off.reflectedLights, 1);
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

// Issue 12, bug 1: a refracting face lit from behind shadows the direct
// light like one lit from the front. Looking straight down at the floor
// point (0, 0, 0) (the middle of a 65 x 49 window), a glass quad at z = -1
// facing +z, the light behind it at (0, 4, -3): the line from the light to
// the point crosses the glass at y = 4 - 4 * 2/3 = 1.33, inside it. With
// ior 1 the bent light is the light itself, scaled by the transmittance
// 0.5; the floor (diffuse 0.5, a vertex at the point) gets the ambient
// 0.1 * 0.5 = 0.05 and 0.5 * (0.5 * N.L) with N.L = 4/5: 0.05 + 0.2 = 0.25,
// 63.75: 64. Without the face's own shadow it got the direct light too:
// 0.05 + 0.4 + 0.2 = 0.65 (166).
TEST(RefLight, GlassLitFromBehindPassesOnlyItsTransmittance) {
  const std::string text = R"(
camera: {position: [0, 8, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 40, near: 0.1, far: 30}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [0, 4, -3], attenuation: [1, 0, 0]}]
materials:
  floor: {diffuse: [0.5, 0.5, 0.5]}
  glass: {kind: refractive, diffuse: [0, 0, 0], ior: 1, transmittance: 0.5}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [4, 1, 4], material: floor}
  - {name: glass, primitive: quad, translate: [0, 1.5, -1], scale: [4, 3, 1], material: glass}
render: {width: 65, height: 49}
)";
  const Scene s = loadSceneText(text, "s.yaml");
  GLContext gl(65, 49, indigoProfile());
  GLCommandStream stream(gl, false);
  renderScene(s, stream);
  EXPECT_NEAR(gl.colorAt(32, 24)[0], 64, 1);
}

}  // namespace
}  // namespace mpr
