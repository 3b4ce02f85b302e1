// In-out refraction (1997 §2): a refracting face with a thickness is a slab,
// its view and its light shifted sideways, not turned; without a thickness
// it stays the 1994 change of medium (refraction_test.cpp).
#include "scene/slab_refraction.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/ref_light.hpp"
#include "algorithms/refraction.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// d at 30 degrees to the normal (0, 0, 1), ior 1.5, T = 0.1:
//   sin(theta_t) = 0.5 / 1.5, theta_t = 19.4712 degrees, cos = 0.9428090;
//   inside t = (1/3, 0, -0.9428090), path T / cos(theta_t) t = (0.0353553, 0, -0.1);
//   path . d = 0.0176777 + 0.0866025 = 0.1042802, d = (0.5, 0, -0.8660254);
//   shift = path - 0.1042802 d = (-0.0167848, 0, -0.0096907),
//   |shift| = T sin(30 - 19.4712) / cos(19.4712) = 0.1 * 0.1827284 / 0.9428090 = 0.0193814.
TEST(SlabRefraction, TheShiftByHand) {
  const DVec3 d(0.5, 0.0, -std::sqrt(0.75));
  for (const DVec3 n : {DVec3(0, 0, 1), DVec3(0, 0, -1)}) {  // either way round
    const DVec3 s = slabShift(d, n, 1.5, 0.1);
    EXPECT_NEAR(s.x, -0.0167848, 1e-7);
    EXPECT_NEAR(s.y, 0.0, 1e-15);
    EXPECT_NEAR(s.z, -0.0096907, 1e-7);
    EXPECT_NEAR(glm::length(s), 0.0193814, 1e-7);
    EXPECT_NEAR(glm::dot(s, d), 0.0, 1e-15);  // sideways
  }
  EXPECT_EQ(slabShift(DVec3(0, 0, -1), DVec3(0, 0, 1), 1.5, 0.1), DVec3(0.0));  // along the normal: straight on
  EXPECT_EQ(slabShift(d, DVec3(0, 0, 1), 1.0, 0.1), DVec3(0.0));               // index 1: nothing bends
}

Scene slabScene(const std::string& glass, const char* camera = "{position: [0, 1.7, 6.5], look_at: [0, 1, 0]}") {
  return loadSceneText(std::string("camera: ") + camera + R"(
lights: [{position: [3, 3, 4]}]
materials: {glass: )" + glass + R"(}
objects:
  - {name: pane, primitive: quad, translate: [1.6, 0.9, 0.8], rotate: [-30, 0, 1, 0], scale: [1.2, 1.6, 1], material: glass}
render: {width: 64, height: 48}
)", "pane.yaml");
}

// The view through a slab is the outer view moved by the shift of the view
// axis's ray where it meets the face: a translation (no turn, no image map).
TEST(SlabRefraction, TheViewIsShiftedNotTurned) {
  const Scene s = slabScene("{kind: refractive, ior: 1.5, thickness: 0.2}");
  const auto faces = findRefFaces(s);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].thickness, static_cast<double>(0.2f));
  const auto r = refractedView(ViewCamera{}, s.camera, faces[0], 0, 1.5, 64.0 / 48.0);
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->totalReflection);
  EXPECT_FALSE(r->view.mapped);
  // The axis from (0, 1.7, 6.5) to (0, 1, 0), where it meets the pane's plane.
  const DVec3 eye(s.camera.position), axis = glm::normalize(DVec3(s.camera.lookAt) - eye);
  const double t = (faces[0].offset - glm::dot(faces[0].normal, eye)) / glm::dot(faces[0].normal, axis);
  ASSERT_GT(t, 0.0);
  const DVec3 shift = slabShift(axis, faces[0].normal, 1.5, faces[0].thickness);
  EXPECT_GT(glm::length(shift), 0.01);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(r->view.world[c][k], c == k ? 1.0 : 0.0);  // no turn
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r->view.world[3][k], -shift[k], 1e-15);
  EXPECT_NEAR(std::sin(r->refracted), std::sin(r->incidence) / 1.5, 1e-12);
}

// Seen at 80 degrees from behind, the change of medium (glass into air,
// eta 1.5) is past its critical angle, a mirror; a slab has air on both
// sides and no critical angle: still a view through it.
TEST(SlabRefraction, NoCriticalAngle) {
  const char* grazing = "{position: [1.6, 0.9, 0.8], look_at: [1.6, 0.9, -5]}";
  // Put the eye 80 degrees off the pane's normal, behind it.
  const Scene base = slabScene("{kind: refractive, ior: 1.5}", grazing);
  const RefFace f = findRefFaces(base)[0];
  const DVec3 along = glm::normalize(glm::cross(f.normal, DVec3(0, 1, 0)));
  const double a = 80.0 * 3.14159265358979323846 / 180.0;
  const DVec3 eye = f.centre + 3.0 * (-std::cos(a) * f.normal + std::sin(a) * along);
  std::string cam = "{position: [" + std::to_string(eye.x) + ", " + std::to_string(eye.y) + ", " + std::to_string(eye.z) +
                    "], look_at: [1.6, 0.9, 0.8]}";
  const Scene medium = slabScene("{kind: refractive, ior: 1.5}", cam.c_str());
  const Scene slab = slabScene("{kind: refractive, ior: 1.5, thickness: 0.1}", cam.c_str());
  const auto rm = refractedView(ViewCamera{}, medium.camera, findRefFaces(medium)[0], 0, 1.5, 64.0 / 48.0);
  const auto rs = refractedView(ViewCamera{}, slab.camera, findRefFaces(slab)[0], 0, 1.5, 64.0 / 48.0);
  ASSERT_TRUE(rm && rs);
  EXPECT_TRUE(rm->totalReflection);
  EXPECT_FALSE(rs->totalReflection);
}

// The light through a slab: the light moved by its ray-to-the-centre's
// shift (the virtual light), and a caster carried with it.
TEST(SlabRefraction, TheLightIsShifted) {
  const Scene s = slabScene("{kind: refractive, ior: 1.5, thickness: 0.2}");
  const RefFace f = findRefFaces(s)[0];
  const DVec3 light(3, 3, 4);
  const auto v = refLightPosition(f, light);
  ASSERT_TRUE(v);
  const DVec3 shift = slabShift(glm::normalize(f.centre - light), f.normal, 1.5, f.thickness);
  EXPECT_EQ(*v, light + shift);
  const DVec3 p(2, 1, 2);
  EXPECT_EQ(transferThroughFace(f, light, *v, p), p + (*v - light));
  // Without a thickness: the light's paraxial image through a change of
  // medium (its distance to the centre times 1.5).
  const Scene medium = slabScene("{kind: refractive, ior: 1.5}");
  const auto m = refLightPosition(findRefFaces(medium)[0], light);
  ASSERT_TRUE(m);
  EXPECT_NEAR(glm::length(*m - f.centre), 1.5 * glm::length(light - f.centre), 1e-12);
  EXPECT_GT(glm::length(*m - light), 10.0 * glm::length(shift));
}

// A thin slab shows what lies behind it almost as a plain transparent face
// does (index 1); the change of medium bends it away. Behind the pane a
// wall with an emitting square: through a 1e-4 slab its pixels are those of
// ior 1 (the shift, 2e-5, is far below a pixel), through the change of
// medium many move.
TEST(SlabRefraction, AThinSlabIsAlmostPlainGlass) {
  const std::string scene = R"(
camera: {position: [0, 1, 6], look_at: [0, 1, 0], fov: 40}
ambient: [0.2, 0.2, 0.2]
materials:
  glass: {kind: refractive, ior: IOR, transmittance: 1, THICK}
  lamp: {diffuse: [0, 0, 0], emission: [1, 1, 1]}
  wall: {diffuse: [0.5, 0.5, 0.5]}
objects:
  - {name: wall, primitive: quad, translate: [0, 1, -2], scale: [8, 4, 1], material: wall}
  - {name: square, primitive: quad, translate: [0.3, 1.2, -1.9], scale: 0.8, material: lamp}
  - {name: pane, primitive: quad, translate: [0, 1, 2], rotate: [-35, 0, 1, 0], scale: [3, 3, 1], material: glass}
render: {width: 64, height: 48}
)";
  const auto render = [&](const char* ior, const char* thick) {
    std::string t = scene;
    t.replace(t.find("IOR"), 3, ior);
    t.replace(t.find("THICK"), 5, thick);
    const Scene s = loadSceneText(t, "s.yaml");
    GLContext gl(64, 48, indigoProfile());
    GLCommandStream stream(gl, false);
    renderScene(s, stream);
    std::vector<Rgba8> px;
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) px.push_back(gl.colorAt(x, y));
    return px;
  };
  const auto plain = render("1.0", "thickness: 0"), slab = render("1.5", "thickness: 0.0001"),
             medium = render("1.5", "thickness: 0");
  int slabDiffers = 0, mediumDiffers = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    slabDiffers += plain[i] != slab[i];
    mediumDiffers += plain[i] != medium[i];
  }
  EXPECT_EQ(slabDiffers, 0);
  EXPECT_GT(mediumDiffers, 20);
}

// A slab passes on light only where it stands in the light's way: with a
// 1.0 slab at 50 degrees (shift 0.39, three pixels on the wall) no wall
// pixel is brighter than without the slab (before the shifted light volume
// was cut to the slab's own shadow, a three-pixel sliver beside the shadow
// got the direct light and the passed-on light both, 1 + T), inside the
// shadow the passed-on light is added, and on its far side a sliver gets
// neither (the rays that leave by the slab's side).
TEST(SlabRefraction, NoPixelGetsTheDirectAndThePassedOnLightBoth) {
  const auto scene = [](bool pane) {
    return loadSceneText(std::string(R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [6, 0, 1]}]
ambient: [0.1, 0.1, 0.1]
materials:
  white: {diffuse: [0.8, 0.8, 0.8]}
)") + (pane ? "  glass: {kind: refractive, ior: 1.5, transmittance: 0.5, thickness: 1.0}\n" : "") + R"(objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1], material: white}
)" + (pane ? "  - {name: pane, primitive: quad, translate: [3, 0, -1.5], scale: 1.2, material: glass}\n" : "") +
                             "render: {width: 64, height: 64}\n",
                         "slab-sliver.yaml");
  };
  const auto colours = [](const Scene& sc) {
    GLContext gl(64, 64, indigoProfile());
    GLCommandStream stream(gl, false);
    renderScene(sc, stream);
    return gl.framebuffer().colorData();
  };
  const std::vector<Rgba8> with = colours(scene(true)), without = colours(scene(false));
  int darker = 0, passedOn = 0;
  std::uint8_t ambientOnly = 255;
  for (std::size_t i = 0; i < with.size(); ++i) ambientOnly = std::min(ambientOnly, with[i][0]);  // the sliver
  for (std::size_t i = 0; i < with.size(); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_LE(with[i][c], without[i][c]) << i % 64 << "," << i / 64;
    darker += with[i][0] < without[i][0];
    passedOn += with[i][0] < without[i][0] && with[i][0] > ambientOnly + 10;
  }
  EXPECT_GT(darker, 200);    // the slab's shadow: about 19 x 19 pixels
  EXPECT_GT(passedOn, 150);  // most of it lit by the passed-on light
  EXPECT_GT(darker - passedOn, 20);  // the sliver by the slab's far edge gets neither
}

}  // namespace
}  // namespace mpr
