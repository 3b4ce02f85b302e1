// The canonical scene of issue 5: one mirror, one light, recursion depth 2,
// one shadow caster, 16x16 pixels. The stencil after every step of Figure 4
// (every apply_stencil, draw_face and shadow pass) is asserted against
// pictures derived by hand from the geometry:
//
//   camera at the origin looking down -z, fovy 90, aspect 1: a point (x, y, -d)
//   lands at window x = 8 + 8 x / d, so on the plane z = -d pixel edges lie at
//   x = d (k / 8 - 1): whole pixels for every rectangle below.
//   wall    z = -4, x, y in [-4, 4]: the whole window.
//   mirror  z = -3, x in [0.375, 2.25], y in [-1.125, 1.125]: window x 9..14,
//           y 5..11, so pixels x 9..13, y 5..10.
//   light   (-2, 0, -3); box x in [-2.25, -1.75], y in [-0.25, 0.25],
//           z in [-3.5, -3.25]. Only the box's front face (z = -3.25) faces
//           the light, so the silhouette is that face's outline. Its shadow on
//           the wall (distance 1 from the light, 0.25 from the face: scale 4)
//           is x in [-3, -1], y in [-1, 1]: pixels x 2..5, y 6..9. The box
//           itself covers window x 2.46..3.69, y 7.38..8.62 (its front face at
//           d = 3.25): pixels x 2..3, y 7..8, where the visible surface is the
//           lit box, not the wall.
//   Seen from the camera all four sides of the volume face it (their outward
//   normals have z > 0 and the camera is in front), so each shadowed wall pixel
//   is entered through exactly one side and never left before the wall: z-pass
//   counts SHAD_ZERO + 1 = 193 there.
//   The mirror reflects the space behind the camera (a wall facing it at
//   z = 1); the virtual view clips at z = -3, which removes the box and its
//   volume: no shadow counts inside the mirror.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/stencil_picture.hpp"

namespace mpr {
namespace {

constexpr const char* kDrawWindowScene = R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], up: [0, 1, 0], fov: 90, near: 0.1, far: 20}
ambient: [0.2, 0.2, 0.2]
lights:
  - {position: [-2, 0, -3], color: [1, 1, 1]}
materials:
  wall: {diffuse: [0.8, 0.8, 0.8]}
  front: {diffuse: [0.6, 0.5, 0.4]}
  red: {diffuse: [0.8, 0.2, 0.2]}
  mirror: {kind: mirror, diffuse: [0.05, 0.05, 0.05], reflectance: 0.9}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1], material: wall}
  - {name: front wall, primitive: quad, translate: [0, 0, 1], rotate: [180, 0, 1, 0], scale: [8, 8, 1], material: front}
  - {name: box, primitive: box, translate: [-2, 0, -3.375], scale: [0.5, 0.5, 0.25], material: red}
  - {name: mirror, primitive: quad, translate: [1.3125, 0, -3], scale: [1.875, 2.25, 1], material: mirror}
render: {width: 16, height: 16, recursion_depth: 2, shadow_recursion_depth: 1}
)";

// SHAD_ZERO everywhere, SHAD_ZERO + 1 on the shadowed wall pixels.
constexpr const char* kShadowCounted = R"(
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 193 193 193 193 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 193 193 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 193 193 192 192 192 192 192 192 192 192 192 192
        192 192 193 193 193 193 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
        192 192 192 192 192 192 192 192 192 192 192 192 192 192 192 192
)";

// The mirror's pixels (.) inside render area level 1.
constexpr const char* kMirrorMask = R"(
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   .   .   .   .   .   1   1
          1   1   1   1   1   1   1   1   1   .   .   .   .   .   1   1
          1   1   1   1   1   1   1   1   1   .   .   .   .   .   1   1
          1   1   1   1   1   1   1   1   1   .   .   .   .   .   1   1
          1   1   1   1   1   1   1   1   1   .   .   .   .   .   1   1
          1   1   1   1   1   1   1   1   1   .   .   .   .   .   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
          1   1   1   1   1   1   1   1   1   1   1   1   1   1   1   1
)";

std::string uniform(int v) {
  std::string row, pic = "\n";
  for (int x = 0; x < 16; ++x) row += (v == 0 ? std::string(".") : std::to_string(v)) + " ";
  for (int y = 0; y < 16; ++y) pic += row + "\n";
  return pic;
}

// kMirrorMask with the mirror's pixels holding `inside` instead of 0.
std::string mirrorHolding(int inside) {
  std::string pic;
  for (const char c : std::string(kMirrorMask)) pic += c == '.' ? std::to_string(inside) : std::string(1, c);
  return pic;
}

struct Step {
  std::string label;
  std::string picture;
};

// The stencil (and every other buffer) at the end of each pass, by label.
std::vector<std::pair<std::string, Framebuffer>> renderCanonical() {
  const Scene scene = loadSceneText(kDrawWindowScene, "canonical.yaml");
  GLContext gl(16, 16, indigoProfile());
  GLCommandStream stream(gl, false);
  std::vector<std::pair<std::string, Framebuffer>> seen;
  stream.onPassEnd([&](const std::string& label) { seen.emplace_back(label, gl.framebuffer()); });
  const RenderResult r = renderScene(scene, stream);
  EXPECT_EQ(r.counts.views, 2u);
  EXPECT_EQ(stream.glErrors(), 0u);
  return seen;
}

TEST(DrawWindowCanonical, StencilAfterEveryStep) {
  const auto seen = renderCanonical();
  const std::string zero = uniform(0), shadZero = uniform(192), level1 = uniform(1);
  // Label (without the routine path), stencil at the end of that pass.
  const std::vector<Step> expected = {
      {"clear | clear every buffer", zero},
      {"ambient | draw_normal_objects(Camera, ZERO)  // ambient only", zero},
      {"render area to SHAD_ZERO | apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)", shadZero},
      {"shadow volumes | make_all_shadows(ALWAYS)", kShadowCounted},
      {"count check | apply_stencil(EQUAL, max, KEEP, max)  // saturated counts?", kShadowCounted},
      {"lit outside the shadows | draw_normal_objects(Camera, SHAD_ZERO)", kShadowCounted},
      {"reset the counts | apply_stencil(GREATER, SHAD_MIN, REPLACE, SHAD_ZERO)", shadZero},
      {"back to ZERO | apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)", zero},
      {"clear | clear_stencil(ZERO)", zero},
      {"render area to REF_LEVEL | apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL)", level1},
      {"mask the face | stencil(EQUAL, REF_LEVEL, REPLACE, ZERO); draw_face(ref_face)", kMirrorMask},
      {"depth to far inside the mask | (the paper is silent: clear the face's pixels)", kMirrorMask},
      // draw_window level 1, inside the mirror only.
      {"ambient | draw_normal_objects(Camera, ZERO)  // ambient only", kMirrorMask},
      {"render area to SHAD_ZERO | apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)", mirrorHolding(192)},
      {"shadow volumes | make_all_shadows(ALWAYS)", mirrorHolding(192)},
      {"count check | apply_stencil(EQUAL, max, KEEP, max)  // saturated counts?", mirrorHolding(192)},
      {"lit outside the shadows | draw_normal_objects(Camera, SHAD_ZERO)", mirrorHolding(192)},
      {"reset the counts | apply_stencil(GREATER, SHAD_MIN, REPLACE, SHAD_ZERO)", mirrorHolding(192)},
      {"back to ZERO | apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)", kMirrorMask},
      // draw_ref_objects level 2: the only face is the one looked through.
      {"render area to REF_LEVEL | apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL)", mirrorHolding(2)},
      {"level done | apply_stencil(EQUAL, REF_LEVEL, REPLACE, ZERO)", kMirrorMask},
      {"blend the face's own colour | two renderings through destination alpha", kMirrorMask},
      // The mirror receives shadows (bug 4): its pixels count the light's
      // volumes (the box's does not reach it: nothing above SHAD_ZERO).
      {"face lit by light 0: its pixels to SHAD_ZERO | apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)", mirrorHolding(192)},
      {"shadows on the face, light 0 | the light's volumes but the face's own, on its pixels", mirrorHolding(192)},
      {"the face lit by light 0 outside the shadows | blend (DST_ALPHA, ONE)", mirrorHolding(192)},
      {"face back to ZERO | apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)", kMirrorMask},
      {"face back to REF_LEVEL | apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL)", level1},
      {"level done | apply_stencil(EQUAL, REF_LEVEL, REPLACE, ZERO)", zero},
  };
  ASSERT_EQ(seen.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const std::string& label = seen[i].first;
    const std::size_t cut = label.rfind(" > ");
    EXPECT_EQ(cut == std::string::npos ? label : label.substr(cut + 3), expected[i].label) << "pass " << i + 1;
    const std::string mismatch = stencilPictureMismatch(seen[i].second, 0, 0, expected[i].picture);
    EXPECT_TRUE(mismatch.empty()) << "after pass " << i + 1 << " \"" << label << "\":\n" << mismatch;
  }
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

// recursion_depth 0 (and the deepest level of any recursion) does not look
// through specular faces: they are drawn as their own colour (the planner's
// note), not left out. A mirror and a glass quad seen head on under ambient
// light 1 and no lamp: material ambient = diffuse 0.5, so 0.5 * 255 = 127.5,
// rounded to even: 128 (the clear colour, 0, where they were left out).
TEST(DrawWindow, FacesNotRecursedIntoAreDrawnAsTheirOwnColour) {
  const std::string text = R"(
camera: {position: [0, 0, 4], look_at: [0, 0, 0], fov: 40, near: 0.1, far: 20}
ambient: [1, 1, 1]
materials:
  mirror: {kind: mirror, diffuse: [0.5, 0.5, 0.5], reflectance: 0.9}
  glass:  {kind: refractive, diffuse: [0.5, 0.5, 0.5], ior: 1.5}
objects:
  - {name: mirror, primitive: quad, translate: [-0.6, 0, 0], material: mirror}
  - {name: glass, primitive: quad, translate: [0.6, 0, 0], material: glass}
render: {width: 32, height: 24, recursion_depth: 0}
)";
  const Scene s = loadSceneText(text, "s.yaml");
  GLContext gl(32, 24, indigoProfile());
  GLCommandStream stream(gl, false);
  renderScene(s, stream);
  // Window x of world x = +-0.6 at the quads' depth: half-width 4 tan(20 deg)
  // * 32/24 = 1.941, so 16 -+ 0.6 / 1.941 * 16 = 11.1 and 20.9.
  EXPECT_EQ(gl.colorAt(11, 12), (Rgba8{128, 128, 128, 255}));
  EXPECT_EQ(gl.colorAt(20, 12), (Rgba8{128, 128, 128, 255}));
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

// Issue 12, bug 2: glass has two sides. The camera behind a glass quad (it
// faces +z, the eye is at z = -4) looks through it at an emitting square:
// with ior 1 the view through is the plain view, blended through
// destination alpha: alpha = 1 - T = 0.5 is stored as round(127.5) = 128,
// so the view through (255) is weighted by 255 - 128 = 127: 255 * 127 / 255
// = 127, and the face's lit colour (diffuse 0, no light) adds 0. Skipped as
// seen from behind, the square showed at 255.
TEST(DrawWindow, GlassIsLookedThroughFromBehind) {
  const std::string text = R"(
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 40, near: 0.1, far: 20}
ambient: [0, 0, 0]
materials:
  glass: {kind: refractive, diffuse: [0, 0, 0], ior: 1, transmittance: 0.5}
  lamp:  {diffuse: [0, 0, 0], emission: [1, 1, 1]}
objects:
  - {name: glass, primitive: quad, scale: 2, material: glass}
  - {name: lamp, primitive: quad, translate: [0, 0, 2], rotate: [180, 0, 1, 0], scale: 3, material: lamp}
render: {width: 32, height: 24, recursion_depth: 1}
)";
  const Scene s = loadSceneText(text, "s.yaml");
  GLContext gl(32, 24, indigoProfile());
  GLCommandStream stream(gl, false);
  const RenderResult r = renderScene(s, stream);
  EXPECT_EQ(r.counts.viewsAtLevel[1], 1);
  EXPECT_EQ(gl.colorAt(16, 12)[0], 127);
  EXPECT_EQ(gl.colorAt(16, 12)[1], 127);
}

}  // namespace
}  // namespace mpr
