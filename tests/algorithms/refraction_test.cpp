// The refracted camera (1994 "Refractions"): Snell's law with the paper's
// two-angle rule, and M3 putting the refracted image of the face where the
// face is on the screen.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/refraction.hpp"
#include "pipeline/quad_to_quad.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

Scene paneScene(double ior, const char* camera = "{position: [0, 1.7, 6.5], look_at: [0, 1, 0]}") {
  return loadSceneText(std::string("camera: ") + camera + R"(
materials: {glass: {kind: refractive, ior: )" + std::to_string(ior) + R"(}}
objects:
  - {name: pane, primitive: quad, translate: [1.6, 0.9, 0.8], rotate: [-30, 0, 1, 0], scale: [1.2, 1.6, 1], material: glass}
render: {width: 64, height: 48}
)", "pane.yaml");
}

TEST(Refraction, TheMapPutsTheRefractedFaceOnTheFace) {
  const Scene s = paneScene(1.5);
  const auto faces = findRefFaces(s);
  ASSERT_EQ(faces.size(), 1u);
  const auto r = refractedView(ViewCamera{}, s.camera, faces[0], 0, 1.5, 64.0 / 48.0);
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->totalReflection);
  EXPECT_TRUE(r->view.mapped);
  // Snell: sin(theta_t) = sin(theta_i) / 1.5.
  EXPECT_NEAR(std::sin(r->refracted), std::sin(r->incidence) / 1.5, 1e-12);
  for (const Vec3& corner : faces[0].polygon) {
    const auto seen = screenOf(ViewCamera{}, s.camera, 64.0 / 48.0, DVec3(corner));
    const auto mapped = screenOf(r->view, s.camera, 64.0 / 48.0, DVec3(corner));
    ASSERT_TRUE(seen && mapped);
    EXPECT_NEAR(mapped->x, seen->x, 1e-9);
    EXPECT_NEAR(mapped->y, seen->y, 1e-9);
  }
}

TEST(Refraction, IndexOneIsThePlainView) {
  const Scene s = paneScene(1.0);
  const auto faces = findRefFaces(s);
  const auto r = refractedView(ViewCamera{}, s.camera, faces[0], 0, 1.0, 64.0 / 48.0);
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->view.mapped);
  EXPECT_EQ(r->view.world, DMat4(1.0));
  EXPECT_EQ(r->incidence, r->refracted);
}

}  // namespace
}  // namespace mpr
