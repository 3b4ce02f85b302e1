// Issue 43, defect 7: where the recursion stops (the deepest level, or
// recursion_depth 0) the specular faces a view does not look through are
// drawn as their own material; pixels derived by hand. Before, the face a
// view looks through was drawn into that view (its own colour over all
// that lay behind it), and glass seen from behind was culled (the clear
// colour, black, where nothing lay behind it).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/scene_renderer.hpp"
#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::depth_runs_out_test {
namespace {

struct Rendered {
  RenderResult result;
  Rgba8 centre;
};

// Red, green and blue as numbers (a failure prints them, not as characters).
std::array<int, 3> rgb(const Rgba8& c) { return {c[0], c[1], c[2]}; }

Rendered render(const std::string& yaml) {
  const Scene scene = loadSceneText(yaml, "s.yaml");
  GLContext gl(32, 24, indigoProfile());
  GLCommandStream stream(gl, false);
  Rendered r;
  r.result = renderScene(scene, stream);
  r.centre = gl.colorAt(16, 12);
  return r;
}

// The camera in front of a pane of glass (facing it, ior 1: the view through
// is the plain view) with an emitting square behind it, recursion_depth 1:
// the view through the pane is the deepest. It must show the square, not
// the pane again: the pane lies on that view's clip plane, and drawn into
// it as its own colour (diffuse 0, no light: black) it covered the square,
// so the pixel was black. With the square seen: alpha = 1 - T = 0.5 is
// stored as round(127.5) = 128, so the view through (255) is weighted by
// 255 - 128 = 127: 255 * 127 / 255 = 127, and the pane's own colour adds 0
// (GlassIsLookedThroughFromBehind is the same from the other side).
TEST(DepthRunsOut, TheFaceAViewLooksThroughIsNotDrawnIntoIt) {
  const Rendered r = render(R"(
camera: {position: [0, 0, 4], look_at: [0, 0, 0], fov: 40, near: 0.1, far: 20}
ambient: [0, 0, 0]
materials:
  glass: {kind: refractive, diffuse: [0, 0, 0], ior: 1, transmittance: 0.5}
  lamp:  {diffuse: [0, 0, 0], emission: [1, 1, 1]}
objects:
  - {name: glass, primitive: quad, scale: 2, material: glass}
  - {name: lamp, primitive: quad, translate: [0, 0, -2], scale: 3, material: lamp}
render: {width: 32, height: 24, recursion_depth: 1}
)");
  ASSERT_EQ(r.result.counts.viewsAtLevel[1], 1);
  EXPECT_EQ(rgb(r.centre), (std::array<int, 3>{127, 127, 127}));
}

// recursion_depth 0, the camera behind a glass quad (it faces +z, the eye is
// at z = -4) with nothing behind it: glass has two sides, so the quad is
// drawn as its own material seen from behind, not culled to the clear
// colour (black). Ambient 1, diffuse 0.4: 0.4 * 255 = 102. Lit instead by a
// light far away on the eye's side (0, 0, -1000), ambient 0: the face
// turned round has the normal -z, toward the light, and every corner
// (+-1, +-1, 0) sees it at N.L = 1000 / sqrt(1000^2 + 2) = 0.999999, so
// 0.4 * 0.999999 * 255 = 101.9999 rounds to 102 (with the front's normal,
// +z, away from the light, it would be 0).
TEST(DepthRunsOut, GlassSeenFromBehindWhereTheRecursionStopsShowsItsOwnMaterial) {
  const char* scene = R"(
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 40, near: 0.1, far: 2000}
ambient: [AMBIENT]
LIGHTS
materials:
  glass: {kind: refractive, diffuse: [0.4, 0.4, 0.4], ior: 1.5, transmittance: 0.8}
objects:
  - {name: glass, primitive: quad, scale: 2, material: glass}
render: {width: 32, height: 24, recursion_depth: 0SHADOWS}
)";
  const auto with = [&](const std::string& ambient, const std::string& lights, const std::string& shadows) {
    std::string s = scene;
    s.replace(s.find("AMBIENT"), 7, ambient);
    s.replace(s.find("LIGHTS"), 6, lights);
    s.replace(s.find("SHADOWS"), 7, shadows);
    return s;
  };
  const Rendered ambient = render(with("1, 1, 1", "lights: []", ""));
  EXPECT_EQ(rgb(ambient.centre), (std::array<int, 3>{102, 102, 102}));
  // Shadows off: the quad is alone (its own shadow volume is not at issue).
  const Rendered lit = render(with("0, 0, 0", "lights: [{position: [0, 0, -1000]}]", ", shadows: false"));
  EXPECT_EQ(rgb(lit.centre), (std::array<int, 3>{102, 102, 102}));
}

// A glass box seen from inside where the recursion stops (recursion_depth
// 0), as the views inside issue 43's glass box see it at their deepest
// level: every face is seen from behind, so every pixel shows the glass's
// own material (ambient 1, diffuse 0.4: 102). Culled, the whole window was
// the clear colour.
TEST(DepthRunsOut, AGlassBoxSeenFromInsideIsItsOwnMaterialEverywhere) {
  const Scene scene = loadSceneText(R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 60, near: 0.1, far: 20}
ambient: [1, 1, 1]
materials:
  glass: {kind: refractive, diffuse: [0.4, 0.4, 0.4], ior: 1.5, transmittance: 0.8}
objects:
  - {name: glass box, primitive: box, scale: 4, material: glass}
render: {width: 32, height: 24, recursion_depth: 0}
)", "s.yaml");
  GLContext gl(32, 24, indigoProfile());
  GLCommandStream stream(gl, false);
  renderScene(scene, stream);
  int own = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) {
      own += rgb(gl.colorAt(x, y)) == std::array<int, 3>{102, 102, 102};
    }
  EXPECT_EQ(own, 32 * 24);
}

}  // namespace
}  // namespace mpr::depth_runs_out_test
