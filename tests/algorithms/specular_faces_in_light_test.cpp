// Issue 43: light the specular faces lose, block, or pass on, on small
// scenes whose pixels are derived by hand or equal another render's.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/ref_face.hpp"
#include "algorithms/ref_light.hpp"
#include "algorithms/scene_renderer.hpp"
#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::specular_faces_in_light_test {
namespace {

std::vector<Rgba8> colours(const std::string& yaml, int w, int h) {
  Scene scene = loadSceneText(yaml, "s.yaml");
  scene.render.width = w;
  scene.render.height = h;
  GLContext gl(w, h, indigoProfile());
  GLCommandStream stream(gl, false);
  renderScene(scene, stream);
  // The picture: red, green, blue (alpha holds the destination alpha the
  // specular faces' blending left, which differs between the pass orders).
  std::vector<Rgba8> c = gl.framebuffer().colorData();
  for (Rgba8& p : c) p[3] = 0;
  return c;
}

Rgba8 at(const std::vector<Rgba8>& c, int w, int x, int y) { return c[static_cast<std::size_t>(y * w + x)]; }

// A mirror lights the wall it faces (its virtual light), and nothing casts a
// shadow: the image must not depend on where shadows stop. Views past
// shadow_recursion_depth lost the virtual light (the mirror's copy of the
// wall went dark), and with shadows off no virtual light was drawn at all.
// With no caster, the shadowed and unshadowed passes add the same light in
// the same order: the same bytes. A mirror of reflectance 0 passes no light
// on: the render differs (so the virtual light is really drawn).
const char* kMirrorRoom = R"(
camera: {position: [0, 1.2, 3], look_at: [0, 1, -1], fov: 60}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [0.8, 1.8, 0.5], attenuation: [1, 0.1, 0]}]
materials:
  mirror: {kind: mirror, diffuse: [0, 0, 0], reflectance: R}
  wall: {diffuse: [0.7, 0.7, 0.7]}
objects:
  - {name: back wall, primitive: quad, translate: [0, 1, -2], scale: [6, 4, 1], material: wall}
  - {name: front wall, primitive: quad, translate: [0, 1, 4], rotate: [180, 0, 1, 0], scale: [6, 4, 1], material: wall}
  - {name: mirror, primitive: quad, translate: [0, 1, -1.9], scale: [1.6, 1.2, 1], material: mirror, casts_shadows: false}
render: {recursion_depth: 2, SETTINGS}
)";

std::string mirrorRoom(const std::string& reflectance, const std::string& settings) {
  std::string s = kMirrorRoom;
  s.replace(s.find("R}"), 1, reflectance);
  s.replace(s.find("SETTINGS"), 8, settings);
  return s;
}

TEST(SpecularFacesInLight, VirtualLightsLightEveryViewShadowedOrNot) {
  const auto shadowed = colours(mirrorRoom("0.8", "shadow_recursion_depth: 2"), 48, 36);
  EXPECT_EQ(colours(mirrorRoom("0.8", "shadow_recursion_depth: 0"), 48, 36), shadowed);
  EXPECT_EQ(colours(mirrorRoom("0.8", "shadows: false"), 48, 36), shadowed);
  EXPECT_NE(colours(mirrorRoom("0", "shadow_recursion_depth: 2"), 48, 36), shadowed);
}

// A mirror is opaque: it shadows the light behind it. Looking straight down
// at the floor point (0, 0, -2) from 6 above (64 x 64, fov 60, the point in
// the middle of the window), the light at (0, 2, 2) in front of a mirror
// standing at z = 0 (x in -0.5..0.5, y in 0.5..1.5, facing the light): the
// ray from the light to (0, 0, -2) crosses z = 0 at y = 1, inside the
// mirror, so the point gets the ambient light only, the same bytes as the
// scene without its light. The floor point (1.35, 0, -2) (pixel (44, 32):
// 1.35 / (6 tan 30) = 0.39 of the half-width) is 1.35 / 2 = 0.675 out at the
// mirror's plane, past its edge at 0.5: lit. Before, a mirror cast no shadow.
const char* kStandingMirror = R"(
camera: {position: [0, 6, -2], look_at: [0, 0, -2], up: [0, 0, -1], fov: 60}
ambient: [0.2, 0.2, 0.2]
LIGHTS
materials:
  mirror: {kind: mirror, reflectance: 0.9}
  floor: {diffuse: [0.5, 0.5, 0.5]}
objects:
  - {name: floor, primitive: plane, scale: [12, 1, 12], material: floor}
  - {name: mirror, primitive: quad, translate: [0, 1, 0], material: mirror}
)";

std::string standingMirror(const std::string& lights) {
  std::string s = kStandingMirror;
  s.replace(s.find("LIGHTS"), 6, lights);
  return s;
}

TEST(SpecularFacesInLight, AMirrorShadowsWhatLiesBehindIt) {
  const auto lit = colours(standingMirror("lights: [{position: [0, 2, 2]}]"), 64, 64);
  const auto dark = colours(standingMirror("lights: []"), 64, 64);
  EXPECT_EQ(at(lit, 64, 32, 32), at(dark, 64, 32, 32));
  EXPECT_GT(at(lit, 64, 44, 32)[0], at(dark, 64, 44, 32)[0] + 20);
}

// A pane of change-of-medium glass turned -20 degrees about y in a closed
// room: its refracted view's image map has a denominator below 1 over part
// of the pane, and depth divided by it passed the far plane there, so that
// part showed nothing but the pane's own colour over the clear colour. The
// pane is black itself here (its own colour adds nothing), and every pixel
// of a closed room with an ambient light shows some surface: none is black.
TEST(SpecularFacesInLight, ATurnedPaneShowsTheRoomBehindIt) {
  const char* room = R"(
camera: {position: [0, 1.6, 6], look_at: [0, 1.0, 0], fov: 50, near: 0.1, far: 50}
ambient: [0.12, 0.12, 0.14]
lights: [{position: [1.0, 3.5, 2.0], attenuation: [1, 0.02, 0.01]}]
materials:
  wall: {diffuse: [0.6, 0.68, 0.8]}
  glass: {kind: refractive, diffuse: [0, 0, 0], ior: 1.5, transmittance: 0.8}
objects:
  - {name: floor, primitive: plane, scale: [8, 1, 10], translate: [0, 0, 1], material: wall}
  - {name: ceiling, primitive: plane, scale: [8, 1, 10], translate: [0, 4, 1], rotate: [180, 1, 0, 0], material: wall}
  - {name: back, primitive: quad, translate: [0, 2, -4], scale: [8, 4, 1], material: wall}
  - {name: left, primitive: quad, translate: [-4, 2, 1], rotate: [90, 0, 1, 0], scale: [10, 4, 1], material: wall}
  - {name: right, primitive: quad, translate: [4, 2, 1], rotate: [-90, 0, 1, 0], scale: [10, 4, 1], material: wall}
  - {name: front, primitive: quad, translate: [0, 2, 6], rotate: [180, 0, 1, 0], scale: [8, 4, 1], material: wall}
  - {name: pane, primitive: quad, translate: [0, 1.2, 1], rotate: [-20, 0, 1, 0], scale: [2, 1.6, 1], material: glass}
)";
  const auto c = colours(room, 80, 60);
  int black = 0;
  for (const Rgba8& p : c) black += p[0] == 0 && p[1] == 0 && p[2] == 0;
  EXPECT_EQ(black, 0);
}

// An object standing on a mirror floor touches the floor's plane: it is
// neither strictly in front of it nor behind, and so cast no shadow in the
// light the floor reflects (its shadows on the walls were missing). Resting
// on it, it counts as in front: the floor's virtual light below has the
// box's volume (CAN'T_INTERSECT) and, since the box's shadow from the light
// falls on the floor, the volume of its mirror image (MUST_INTERSECT).
TEST(SpecularFacesInLight, AnObjectStandingOnAMirrorShadowsItsLight) {
  const Scene scene = loadSceneText(R"(
lights: [{position: [1, 3, 1]}]
materials: {mirror: {kind: mirror, reflectance: 0.6}}
objects:
  - {name: floor, primitive: quad, rotate: [-90, 1, 0, 0], scale: [6, 6, 1], material: mirror}
  - {name: box, primitive: box, translate: [0, 0.5, 0]}
)", "s.yaml");
  const std::vector<ReflectedLight> lights = reflectedLights(scene, findRefFaces(scene));
  ASSERT_EQ(lights.size(), 1u);
  ASSERT_EQ(lights[0].shadows.size(), 2u);
  EXPECT_FALSE(lights[0].shadows[0].alwaysZFail);  // the box itself
  EXPECT_TRUE(lights[0].shadows[1].alwaysZFail);   // its mirror image, not drawn
}

}  // namespace
}  // namespace mpr::specular_faces_in_light_test
