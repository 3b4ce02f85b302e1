// The refracted camera (1994 "Refractions"): Snell's law with the paper's
// two-angle rule, and M3 putting the refracted image of the face where the
// face is on the screen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/refraction.hpp"
#include "algorithms/scene_renderer.hpp"
#include "algorithms/quad_to_quad.hpp"
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

// Index of refraction 1 is plain transparency, bit for bit: a clear pane
// (transmittance 1, so its own colour weighs nothing) in front of a wall and
// a box renders the same colour bytes as the scene without the pane. (Nothing
// crosses the pane's plane, whose clip plane would otherwise cut triangles.)
TEST(Refraction, IndexOneIsPlainTransparencyBitForBit) {
  const std::string base = R"(
camera: {position: [0.3, 0.2, 0], look_at: [0, 0, -1], fov: 70, near: 0.1, far: 20}
lights: [{position: [1, 1, -1]}]
materials:
  red: {diffuse: [0.8, 0.2, 0.2], specular: [0.3, 0.3, 0.3], shininess: 20}
objects:
  - {primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {primitive: box, translate: [-0.4, -0.2, -3], scale: 0.6, material: red}
)";
  const std::string pane = "  - {primitive: quad, translate: [0, 0, -1.5], rotate: [20, 0, 1, 0], material: clear}\n";
  auto render = [](const std::string& text) {
    const Scene s = loadSceneText(text + "render: {width: 32, height: 24}\n", "pane.yaml");
    GLContext gl(32, 24, indigoProfile());
    GLCommandStream stream(gl, false);
    const RenderResult r = renderScene(s, stream);
    EXPECT_EQ(stream.glErrors(), 0u);
    return std::make_pair(gl.framebuffer().colorData(), r.counts.views);
  };
  const auto [without, viewsWithout] = render(base);
  // The pane's material with the pane (a material no object has is refused).
  std::string withClear = base;
  withClear.insert(withClear.find("  red:"), "  clear: {kind: refractive, ior: 1, transmittance: 1, diffuse: [0.5, 0.5, 0.5]}\n");
  const auto [with, viewsWith] = render(withClear + pane);
  EXPECT_EQ(viewsWithout, 1u);
  EXPECT_EQ(viewsWith, 2u);
  ASSERT_EQ(with.size(), without.size());
  int differ = 0;
  for (std::size_t i = 0; i < with.size(); ++i) {
    // Alpha is the bookkeeping channel of the blend (destination alpha).
    const bool same = with[i][0] == without[i][0] && with[i][1] == without[i][1] && with[i][2] == without[i][2];
    if (!same && ++differ <= 5) ADD_FAILURE() << "pixel " << i % 32 << "," << i / 32;
  }
  EXPECT_EQ(differ, 0);
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

namespace mpr {
namespace {

// Where M3 is applied (render.refraction_map). The depth written inside the
// refracted view, at the end of its ambient pass: the paper's 4x4 with Z
// zeroed sends every point to NDC z = 0, window depth 0.5, stored as
// rint(0.5 * (2^24 - 1)) = 8388608 on every pixel ("precludes the use of the
// Z-buffer"); Z kept (on the projection or by the end-of-pipeline stage), the
// wall and the box behind the pane keep their many depths. Every mapping
// draws the same pixels of the mask.
TEST(Refraction, WhereTheMapIsAppliedDecidesTheDepth) {
  struct Seen {
    std::vector<std::uint32_t> depths;  // drawn pixels of the mask
    std::string trace;
  };
  auto render = [](const char* placement) {
    const Scene s = loadSceneText(std::string(R"(
camera: {position: [0.3, 0.2, 0], look_at: [0, 0, -1], fov: 70, near: 0.1, far: 20}
materials: {glass: {kind: refractive, ior: 1.5}}
objects:
  - {primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {primitive: box, translate: [-0.4, -0.2, -3], scale: 0.6}
  - {primitive: quad, translate: [0, 0, -1.5], rotate: [20, 0, 1, 0], material: glass}
render: {width: 32, height: 24, refraction_map: )") + placement + "}\n", "map.yaml");
    GLContext gl(32, 24, indigoProfile());
    GLCommandStream stream(gl, true);
    Seen seen;
    stream.onPassEnd([&](const std::string& label) {
      if (label.find("draw_window level 1 > ambient") == std::string::npos) return;
      for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x)
          if (gl.stencilAt(x, y) == 0 && gl.depthAt(x, y) != 16777215u) seen.depths.push_back(gl.depthAt(x, y));
    });
    renderScene(s, stream);
    EXPECT_EQ(stream.glErrors(), 0u);
    seen.trace = stream.trace();
    return seen;
  };
  const Seen zeroed = render("projection_zeroed_z"), kept = render("projection"), stage = render("end_of_pipeline");
  ASSERT_GT(zeroed.depths.size(), 20u);
  for (std::uint32_t d : zeroed.depths) EXPECT_EQ(d, 8388608u);
  auto distinct = [](std::vector<std::uint32_t> v) {
    std::sort(v.begin(), v.end());
    return std::unique(v.begin(), v.end()) - v.begin();
  };
  EXPECT_GT(distinct(kept.depths), 20);
  EXPECT_GT(distinct(stage.depths), 20);
  EXPECT_EQ(kept.depths.size(), zeroed.depths.size());
  EXPECT_EQ(stage.depths.size(), kept.depths.size());
  // The stage is not a GL call: it is the @window_map directive
  // (docs/gl-script-directives.md), so the trace replays it.
  EXPECT_NE(stage.trace.find("\n@window_map "), std::string::npos);
  EXPECT_EQ(kept.trace.find("\n@window_map "), std::string::npos);
}

}  // namespace
}  // namespace mpr
