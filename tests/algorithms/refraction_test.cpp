// The refracted camera (1994 "Refractions"): Snell's law with the paper's
// two-angle rule, and M3 putting the refracted image of the face where the
// face is on the screen.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/refraction.hpp"
#include "algorithms/scene_renderer.hpp"
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

// Translucency by fog: a slab 3 units in front of a wall, fog_distance 1, so
// the wall lies past the fog's end. Seen through the slab, before the slab's
// own colour is blended in, every wall pixel is exactly the fog colour (the
// ambient pass fogs to the colour, the light pass to black: 0.6, 0.4, 0.2 ->
// 153, 102, 51); outside the slab the wall is unfogged.
TEST(Translucency, FogReachesTheMaterialColourAtFogDistance) {
  const Scene s = loadSceneText(R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [0, 0, -2]}]
materials: {milk: {kind: translucent, ior: 1, diffuse: [0.6, 0.4, 0.2], fog_distance: 1}}
objects:
  - {primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {primitive: quad, translate: [0, 0, -1], material: milk}
render: {width: 16, height: 16}
)", "milk.yaml");
  GLContext gl(16, 16, indigoProfile());
  GLCommandStream stream(gl, false);
  std::vector<Rgba8> beforeBlend, direct;
  stream.onPassEnd([&](const std::string& label) {
    if (label.find("draw_window level 0 > light 0") != std::string::npos) direct = gl.framebuffer().colorData();
    if (label.find("draw_window level 1 > light 0") != std::string::npos) beforeBlend = gl.framebuffer().colorData();
  });
  const RenderResult r = renderScene(s, stream);
  EXPECT_EQ(r.counts.views, 2u);
  ASSERT_EQ(beforeBlend.size(), 256u);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const bool inSlab = x >= 4 && x < 12 && y >= 4 && y < 12;  // NDC +-0.5 at distance 1
      const Rgba8 c = beforeBlend[static_cast<std::size_t>(y * 16 + x)];
      if (inSlab) EXPECT_EQ(c, (Rgba8{153, 102, 51, 255})) << x << "," << y;
      else EXPECT_EQ(c, direct[static_cast<std::size_t>(y * 16 + x)]) << x << "," << y;
    }
}

}  // namespace
}  // namespace mpr
