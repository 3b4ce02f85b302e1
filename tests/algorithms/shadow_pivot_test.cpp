// The pivot (1997 §4.4, Fig. 7): far nodes moved by the jitter times a2/a1
// (b2/b1), ratios computed by hand; a pivoted volume is the jittered one
// while the silhouette stays; pivot renders against images.
#include "algorithms/shadow_pivot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/scene_renderer.hpp"
#include "algorithms/shadow_test_support.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// The light at L = (0, 4, 0), an edge from A = (1, 2, 0) to B = (-1, 2, 0.5),
// extruded to R = 10 from the light:
//   a1 = |A - L| = sqrt(5) = 2.2360680, a2 = 10 - a1 = 7.7639320,
//   a2 / a1 = 3.4721360; A' = L + 10 (1, -2, 0) / sqrt(5) = (4.4721360, -4.9442719, 0);
//   b1 = |B - L| = sqrt(5.25) = 2.2912878, b2 / b1 = 7.7087122 / 2.2912878 = 3.3643578;
//   B' = L + 10 (-1, -2, 0.5) / sqrt(5.25) = (-4.3643578, -4.7287156, 2.1821789).
// A jitter J = (0.5, 0, 0) moves them by -J a2/a1 = (-1.7360680, 0, 0) and
// -J b2/b1 = (-1.6821789, 0, 0).
TEST(ShadowPivot, FarNodesMoveByTheRatiosOfFigure7) {
  const Vec3 L(0, 4, 0), A(1, 2, 0), B(-1, 2, 0.5f);
  const Vec3 a = extrudeFromLight(A, L, 10.0), b = extrudeFromLight(B, L, 10.0);
  EXPECT_NEAR(a.x, 4.4721360, 1e-5);
  EXPECT_NEAR(a.y, -4.9442719, 1e-5);
  EXPECT_NEAR(b.x, -4.3643578, 1e-5);
  EXPECT_NEAR(b.z, 2.1821789, 1e-5);
  const DVec3 J(0.5, 0.0, 0.0);
  const Vec3 am = pivotFarNode(A, a, L, J), bm = pivotFarNode(B, b, L, J);
  EXPECT_NEAR(am.x, 4.4721360 - 1.7360680, 1e-5);
  EXPECT_NEAR(am.y, -4.9442719, 1e-5);
  EXPECT_NEAR(am.z, 0.0, 1e-6);
  EXPECT_NEAR(bm.x, -4.3643578 - 1.6821789, 1e-5);
  EXPECT_NEAR(bm.y, -4.7287156, 1e-5);
  EXPECT_NEAR(bm.z, 2.1821789, 1e-5);
  // The moved node lies on the ray from the jittered light through the node:
  // A'm - (L + J) = (2.2360680, -8.9442719, 0) = 4.4721360 (A - (L + J)).
  const DVec3 toA = DVec3(A) - (DVec3(L) + J), toAm = DVec3(am) - (DVec3(L) + J);
  EXPECT_NEAR(glm::length(glm::cross(glm::normalize(toA), glm::normalize(toAm))), 0.0, 1e-6);
  EXPECT_NEAR(glm::length(toAm) / glm::length(toA), 4.4721360, 1e-5);
}

// A box's volume pivoted by a jitter that keeps its silhouette (the light
// stays above the top face) is the jittered light's volume: the same
// silhouette and light cap, every far node on the jittered ray through its
// near node, and still watertight.
TEST(ShadowPivot, APivotedVolumeIsTheJitteredVolumeWhileTheSilhouetteStays) {
  const Mesh box = test::boxAt(Vec3(0, 1.9f, 0), Vec3(2, 0.2f, 2));
  const BoundingSphere receivers{DVec3(0, 1, 0), 12.0};
  const Vec3 L(0, 4, 0);
  const DVec3 J(0.3, 0.0, -0.4);
  const ShadowVolume base = pivotBaseVolume(buildShadowVolume(box, L, receivers), 0.5);
  const ShadowVolume moved = pivotShadowVolume(base, J);
  const ShadowVolume rebuilt = buildShadowVolume(box, Vec3(DVec3(L) + J), receivers);
  ASSERT_EQ(moved.sides.size(), rebuilt.sides.size());
  EXPECT_EQ(moved.lightCap, rebuilt.lightCap);
  EXPECT_EQ(test::balanceViolations(moved.triangles()), 0);
  for (std::size_t i = 0; i < moved.sides.size(); ++i) {
    EXPECT_EQ(moved.sides[i][0], rebuilt.sides[i][0]);
    EXPECT_EQ(moved.sides[i][1], rebuilt.sides[i][1]);
    for (int k : {0, 1}) {
      const DVec3 nearNode(moved.sides[i][static_cast<std::size_t>(k)]);
      const DVec3 far(moved.sides[i][static_cast<std::size_t>(3 - k)]);
      const DVec3 truth = glm::normalize(DVec3(rebuilt.sides[i][static_cast<std::size_t>(3 - k)]) - nearNode);
      EXPECT_NEAR(glm::length(glm::cross(glm::normalize(far - nearNode), truth)), 0.0, 1e-6);
      // Beyond the receivers from the jittered light: at least R0 + r.
      EXPECT_GE(glm::length(far - (DVec3(L) + J)), rebuilt.extrusionRadius) << i;
    }
  }
}

// The scene of darkness_levels_test.cpp: a thin box under a light of radius
// 2 whose two samples both stay above the box's top, so both see the same
// silhouette: the pivot's images are the images method's, byte for byte,
// with the volumes built once.
const char* kPivotScene = R"(
camera: {position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 43.60281897270362, near: 1, far: 30}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [0, 4, 0], radius: 2, attenuation: [1, 0, 0]}]
materials: {grey: {diffuse: [0.8, 0.8, 0.8]}}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [16, 1, 16], material: grey}
  - {name: box, primitive: box, translate: [0, 1.9, 0], scale: [2, 0.2, 2], material: grey}
render: {width: 12, height: 8, soft_shadow_samples: 2, soft_shadow_method: pivot}
)";

TEST(ShadowPivot, EqualsImagesWhereTheSilhouetteStays) {
  const Scene pivot = loadSceneText(kPivotScene, "s.yaml");
  const Scene images = loadSceneText(kPivotScene, "s.yaml", {"render.soft_shadow_method=images"});
  GLContext gp(12, 8, indigoProfile()), gi(12, 8, indigoProfile());
  GLCommandStream sp(gp, false), si(gi, false);
  const RenderResult rp = renderScene(pivot, sp), ri = renderScene(images, si);
  EXPECT_EQ(rp.plan.images, 2);
  EXPECT_EQ(rp.counts.lightPasses, rp.plan.predictedLightPasses());
  EXPECT_EQ(rp.counts.shadowPasses, rp.plan.predictedShadowPasses());
  EXPECT_EQ(rp.counts.shadowPasses, ri.counts.shadowPasses);
  int penumbra = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 12; ++x) {
      EXPECT_EQ(gp.colorAt(x, y), gi.colorAt(x, y)) << "pixel " << x << ", " << y;
      penumbra += gp.colorAt(x, y)[0] != gp.colorAt(0, 0)[0];
    }
  EXPECT_GT(penumbra, 20);
}

// Where the silhouette changes with the jitter the pivot keeps the centre's.
// A block standing on the floor (x, z in [-0.5, 0.5], y in [0, 1.1]) lit
// from (1, 4, 0), radius 1, on a disc facing the scene's middle: samples
// past z = +-0.5 also light the block's +z or -z side, whose far edge widens
// their true shadow sideways; the pivoted volumes keep the centre's
// silhouette (top and +x side), so in those images a sliver along the
// shadow's z sides stays lit. Measured: 5 penumbra pixels, on the shadow's
// side (window x < 31.5, the block's middle), each lighter by one image's
// share of the light (11 of 255); everything else, the umbra included, the
// same bytes.
TEST(ShadowPivot, DiffersFromImagesWhereTheSilhouetteChanges) {
  const std::string scene = R"(
camera: {position: [0, 8, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 40, near: 0.1, far: 30}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [1, 4, 0], radius: 1, attenuation: [1, 0, 0]}]
materials: {grey: {diffuse: [0.8, 0.8, 0.8]}}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [8, 1, 8], material: grey}
  - {name: block, primitive: box, translate: [0, 0.55, 0], scale: [1, 1.1, 1], material: grey}
render: {width: 64, height: 48, soft_shadow_samples: 16, soft_shadow_method: pivot}
)";
  const Scene pivot = loadSceneText(scene, "s.yaml");
  const Scene images = loadSceneText(scene, "s.yaml", {"render.soft_shadow_method=images"});
  GLContext gp(64, 48, indigoProfile()), gi(64, 48, indigoProfile()), g1(64, 48, indigoProfile());
  GLCommandStream sp(gp, false), si(gi, false), s1(g1, false);
  renderScene(pivot, sp);
  renderScene(images, si);
  // One image's share: the brightest the light makes the floor, over 16.
  renderScene(loadSceneText(scene, "s.yaml", {"render.soft_shadow_samples=1"}), s1);
  int brightest = 0;
  for (int py = 0; py < 48; ++py)
    for (int x = 0; x < 64; ++x) brightest = std::max(brightest, g1.colorAt(x, py)[0] - 20);
  const int share = (brightest + 15) / 16;
  int differ = 0;
  for (int py = 0; py < 48; ++py)
    for (int x = 0; x < 64; ++x) {
      if (gp.colorAt(x, py) == gi.colorAt(x, py)) continue;
      ++differ;
      EXPECT_LT(x, 32) << "pixel " << x << ", " << py;
      EXPECT_GT(gp.colorAt(x, py)[0], gi.colorAt(x, py)[0]) << "pixel " << x << ", " << py;
      EXPECT_LE(gp.colorAt(x, py)[0] - gi.colorAt(x, py)[0], share + 1) << "pixel " << x << ", " << py;
    }
  EXPECT_GT(differ, 0);
  EXPECT_EQ(gp.colorAt(28, 23), gi.colorAt(28, 23));  // the umbra beside the block
}

}  // namespace
}  // namespace mpr
