// Bug 4 of issue 12: mirrors and glass receive shadows (the 1997 paper casts
// shadows on partially specular surfaces, §7.3). Their own colour, the
// (1 - r) part blended over the view through them, is lit per light where
// no shadow volume (but their own) encloses them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// A face in the plane z = 0 facing +z, 4 x 4, lit from (0, 0, 4) straight
// in front; a box of 0.5 at (0, 0, 2) between: its shadow on the face is
// the box's front square scaled about the light by 4 / (4 - 2.25) = 2.29,
// x, y in [-0.57, 0.57]. The camera at (3, 0, 4) looks at the face's
// centre; the box hides the face around (-3, 0, 0) only. What the face
// shows through it is empty (black): behind a mirror's reflection at the
// centre and at (0, 1.5, 0) lies nothing, nor behind the glass. So the
// face's pixels hold (1 - r) of its own colour: at the centre, in the
// shadow, the ambient part alone; at (0, 1.5, 0) the light's part too.
std::string scene(const std::string& material, const std::string& light) {
  return R"(
camera: {position: [3, 0, 4], look_at: [0, 0, 0], fov: 60, near: 0.1, far: 30}
ambient: [0.2, 0.2, 0.2]
lights: [{position: [0, 0, 4], color: )" + light + R"(, attenuation: [1, 0, 0]}]
materials:
  face: )" + material + R"(
  grey: {diffuse: [0.5, 0.5, 0.5]}
objects:
  - {name: face, primitive: quad, scale: [4, 4, 1], material: face}
  - {name: box, primitive: box, translate: [0, 0, 2], scale: 0.5, material: grey}
render: {width: 64, height: 48}
)";
}

struct Pixels {
  int centre, above;
};

// The window pixels of (0, 0, 0) and (0, 1.5, 0): the camera at (3, 0, 4)
// looks at the origin, so the centre is pixel (32, 24) (the view axis);
// (0, 1.5, 0) is at distance 5 along the axis and 1.5 up: tan = 0.3, over
// tan(30 deg) = 0.5774 of the half-height 24: 12.5 pixels above.
Pixels render(const std::string& text) {
  const Scene s = loadSceneText(text, "s.yaml");
  GLContext gl(64, 48, indigoProfile());
  GLCommandStream stream(gl, false);
  const RenderResult r = renderScene(s, stream, {}, false);
  EXPECT_EQ(r.counts.lightPasses, r.plan.predictedLightPasses());
  EXPECT_EQ(r.counts.shadowPasses, r.plan.predictedShadowPasses());
  return {gl.colorAt(32, 24)[0], gl.colorAt(32, 36)[0]};
}

void expectShadowed(const std::string& material) {
  const Pixels lit = render(scene(material, "[1, 1, 1]"));
  const Pixels dark = render(scene(material, "[0, 0, 0]"));
  // In the shadow: the ambient part alone, as with the light off.
  EXPECT_EQ(lit.centre, dark.centre) << material;
  // Outside it: the light's part too.
  EXPECT_GT(lit.above, dark.above + 40) << material;
}

TEST(ShadowsOnSpecularFaces, AMirrorReceivesTheBoxsShadow) {
  expectShadowed("{kind: mirror, diffuse: [0.8, 0.8, 0.8], reflectance: 0.5}");
}

TEST(ShadowsOnSpecularFaces, GlassReceivesTheBoxsShadowNotItsOwn) {
  expectShadowed("{kind: refractive, diffuse: [0.8, 0.8, 0.8], ior: 1.0, transmittance: 0.5}");
  expectShadowed("{kind: refractive, diffuse: [0.8, 0.8, 0.8], ior: 1.5, transmittance: 0.5, thickness: 0.05}");
}

}  // namespace
}  // namespace mpr
