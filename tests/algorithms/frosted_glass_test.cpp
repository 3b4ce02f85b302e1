// Frosted glass by stochastic shear (1997 §3): the shear about the face
// normal, its samples, and what the accumulated images change.
#include <gtest/gtest.h>

#include <set>

#include "algorithms/image_samples.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

DVec3 apply(const DMat4& m, DVec3 p) { return DVec3(m * DVec4(p, 1.0)); }

// A face at z = 1 facing +z: a point 2 behind it, (0.3, 0.4, -1), moves
// within its plane z = -1 by X t + Y b times -2, t and b the face's tangent
// axes (any orthonormal pair in the plane): a distance of 2 |(0.1, 0.2)| =
// 2 sqrt(0.05). Points on the face do not move.
TEST(FrostedGlass, TheShearIsLinearInTheDistanceFromTheFace) {
  const DMat4 s = shearAboutFace(DVec3(0, 0, 1), DVec3(0, 0, 1), DVec2(0.1, 0.2));
  const DVec3 moved = apply(s, DVec3(0.3, 0.4, -1.0));
  EXPECT_NEAR(moved.z, -1.0, 1e-15);
  EXPECT_NEAR(glm::length(DVec2(moved.x - 0.3, moved.y - 0.4)), 2.0 * std::sqrt(0.05), 1e-12);
  for (const DVec3 p : {DVec3(0, 0, 1), DVec3(5, -3, 1), DVec3(-0.25, 0.5, 1)})
    EXPECT_NEAR(glm::length(apply(s, p) - p), 0.0, 1e-12);
  // A face turned to +x at x = 2: a point 3 behind it keeps x and moves by
  // 3 |(X, Y)| in the face's plane; twice as far, twice as much.
  const DMat4 t = shearAboutFace(DVec3(2, 0, 0), DVec3(1, 0, 0), DVec2(0.05, 0.0));
  const DVec3 a = apply(t, DVec3(-1, 1, 1)), b = apply(t, DVec3(-4, 1, 1));
  EXPECT_NEAR(a.x, -1.0, 1e-15);
  EXPECT_NEAR(glm::length(a - DVec3(-1, 1, 1)), 0.15, 1e-12);
  EXPECT_NEAR(glm::length(b - DVec3(-4, 1, 1)), 0.30, 1e-12);
}

TEST(FrostedGlass, ShearSamplesAreFixedAndScaleWithTheMultiplier) {
  EXPECT_EQ(frostedShear(0.05, 1, 0), DVec2(0.0));
  EXPECT_EQ(frostedShear(0.0, 12, 3), DVec2(0.0));
  std::set<std::pair<double, double>> seen;
  for (int i = 0; i < 12; ++i) {
    const DVec2 a = frostedShear(0.05, 12, i), b = frostedShear(0.1, 12, i);
    EXPECT_NEAR(b.x, 2.0 * a.x, 1e-15);
    EXPECT_NEAR(b.y, 2.0 * a.y, 1e-15);
    EXPECT_EQ(frostedShear(0.05, 12, i + 12), a);  // the table cycles
    seen.insert({a.x, a.y});
  }
  EXPECT_EQ(seen.size(), 12u);
}

// Outside the pane every image is the same, so the accumulation returns it
// exactly (12 <= 64: the accumulation test's bound): the frosted scene and
// the same scene with shear 0 agree byte for byte there; through the pane
// they differ (the shear blurs what lies behind it). The light stands behind
// the camera at its height, so what the pane lets it light (and scatters,
// frosted_light_test.cpp) is seen through the pane too: at the bar (z = -1)
// its cone is 1.4 wide, 0.28 rad from the eye against the pane's 0.33; on
// the floor it starts at z = -4, 7.1 degrees below the eye's horizon, above
// the pane's lower edge at 9.5.
TEST(FrostedGlass, OnlyThePaneChanges) {
  const std::string text = R"(
camera: {position: [0, 1, 4], look_at: [0, 1, 0], fov: 45, near: 0.1, far: 30}
ambient: [0.3, 0.3, 0.3]
lights: [{position: [0, 1, 6]}]
materials:
  frost: {kind: frosted, diffuse: [0.8, 0.8, 0.8], transmittance: 0.8, shear: 0.08, samples: 12, fog_distance: 20}
  red:   {diffuse: [0.9, 0.1, 0.1]}
  floor: {diffuse: [0.5, 0.5, 0.5]}
objects:
  - {name: floor, primitive: plane, scale: [10, 1, 10], material: floor}
  - {name: pane, primitive: quad, translate: [0, 1, 1], scale: [1, 1, 1], material: frost}
  - {name: bar, primitive: box, translate: [0, 1, -1], scale: [0.1, 2, 0.1], material: red}
render: {width: 48, height: 36}
)";
  const Scene frosted = loadSceneText(text, "s.yaml");
  std::string clearText = text;
  clearText.replace(clearText.find("shear: 0.08"), 11, "shear: 0.00");
  const Scene clear = loadSceneText(clearText, "s.yaml");
  EXPECT_EQ(accumulatedImages(frosted), 12);
  GLContext a(48, 36, indigoProfile()), b(48, 36, indigoProfile());
  GLCommandStream sa(a, false), sb(b, false);
  renderScene(frosted, sa);
  renderScene(clear, sb);
  // The pane, 3 from the eye, 1 wide: half-height 3 tan 22.5 = 1.243, so it
  // covers window y 18 -+ 0.5/1.243*18 = 10.8 .. 25.2 and x 24 -+ 7.2.
  int inside = 0, outside = 0;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 48; ++x) {
      const bool pane = x >= 18 && x <= 30 && y >= 12 && y <= 24;
      const bool near = x >= 15 && x <= 33 && y >= 9 && y <= 27;
      if (!near) outside += a.colorAt(x, y) != b.colorAt(x, y);
      if (pane) inside += a.colorAt(x, y) != b.colorAt(x, y);
    }
  EXPECT_EQ(outside, 0);
  EXPECT_GT(inside, 10);
}

// A glossy mirror (roughness 0.125, 8 samples): its reflected view sheared
// by 2 alpha = 0.25 per unit of distance from the mirror, one shear an
// image; everything but the mirror repeats exactly in every image, so only
// the mirror's pixels differ from the same mirror without roughness.
TEST(GlossyMirror, OnlyTheReflectionBlurs) {
  const std::string text = R"(
camera: {position: [0, 1, 4], look_at: [0, 1, 0], fov: 45, near: 0.1, far: 30}
ambient: [0.3, 0.3, 0.3]
lights: [{position: [0, 4, 3]}]
materials:
  mirror: {kind: mirror, diffuse: [0.1, 0.1, 0.1], reflectance: 0.9, roughness: 0.125, samples: 8}
  red:    {diffuse: [0.9, 0.1, 0.1]}
  floor:  {diffuse: [0.5, 0.5, 0.5]}
objects:
  - {name: floor, primitive: plane, scale: [10, 1, 10], material: floor}
  - {name: mirror, primitive: quad, translate: [0, 1, -1], scale: [1, 1, 1], material: mirror}
  - {name: bar, primitive: box, translate: [0.2, 1, 1], scale: [0.1, 2, 0.1], material: red}
render: {width: 48, height: 36}
)";
  const Scene glossy = loadSceneText(text, "s.yaml");
  const Scene sharp = loadSceneText(text, "s.yaml", {"render.frosted=false"});
  EXPECT_EQ(accumulatedImages(glossy), 8);
  EXPECT_EQ(accumulatedImages(sharp), 1);
  GLContext a(48, 36, indigoProfile()), b(48, 36, indigoProfile());
  GLCommandStream sa(a, false), sb(b, false);
  renderScene(glossy, sa);
  renderScene(sharp, sb);
  // The mirror, 5 from the eye, 1 wide: half-height 5 tan 22.5 = 2.071, so
  // window x 24 -+ 0.5/2.071*18 = 19.7 .. 28.3, y 13.7 .. 22.3.
  int inside = 0, outside = 0;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 48; ++x) {
      const bool mirror = x >= 20 && x <= 28 && y >= 14 && y <= 22;
      const bool near = x >= 18 && x <= 30 && y >= 12 && y <= 24;
      if (!near) outside += a.colorAt(x, y) != b.colorAt(x, y);
      if (mirror) inside += a.colorAt(x, y) != b.colorAt(x, y);
    }
  EXPECT_EQ(outside, 0);
  EXPECT_GT(inside, 5);
}

}  // namespace
}  // namespace mpr
