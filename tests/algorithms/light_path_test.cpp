// Light through several specular faces (1997 §4.2-4.3, Fig. 5-6): virtual
// lights of virtual lights, each light volume reduced by every face on its
// path by stenciling the constituent volumes.
//
// Hand derivation of the two-mirror scene (16x16, camera at the origin
// looking down -z, fovy 90, the wall at z = -4 filling the view: a wall point
// (X, Y) lands at window (8 + 2X, 8 + 2Y)):
// - mirror A: half-size 0.25 at z = -3 facing +z; mirror B: half-size 1 at
//   z = -1 facing -z (the camera sees it from behind: culled, the wall shows
//   through it). The light at (0, 0, -2) is in front of both.
// - Virtual lights: through A (0, 0, -4); through B (0, 0, 0); A then B:
//   (0, 0, -4) reflected in z = -1, (0, 0, 2); B then A: (0, 0, 0) reflected
//   in z = -3, (0, 0, -6).
// - The path A, B: B's light volume from (0, 0, 2) (distance 3 to B, 6 to
//   the wall) covers |X|, |Y| <= 2 on the wall: window 4..12, pixels 4..11.
//   A carried through B is A' at z = 1 (half-size 0.25, distance 1), whose
//   volume covers |X|, |Y| <= 1.5: window 5..11, pixels 5..10. Every shadow
//   value is raised twice (194) and each volume counted inverted: 192 inside
//   both, 193 inside B's only, 194 outside. A itself (window 7.33..8.67,
//   pixels 7..8) is inside both volumes too: 192.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>

#include "algorithms/light_path.hpp"
#include "algorithms/ref_light.hpp"
#include "algorithms/render_plan.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/stencil_picture.hpp"

namespace mpr {
namespace {

// B is turned by glRotate-style float sines (sin 180° is not 0 in float):
// its plane is z = -1 to about 1e-7, so positions are compared to 1e-6.
void expectNear(DVec3 a, DVec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
  EXPECT_NEAR(a.z, b.z, 1e-6);
}

constexpr const char* kTwoMirrors = R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 90, near: 0.1, far: 20}
lights: [{position: [0, 0, -2]}]
materials: {mirror: {kind: mirror, reflectance: 0.5}}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {name: A, primitive: quad, translate: [0, 0, -3], scale: 0.5, material: mirror}
  - {name: B, primitive: quad, translate: [0, 0, -1], rotate: [180, 0, 1, 0], scale: 2, material: mirror}
render: {width: 16, height: 16, recursion_depth: 1, shadow_recursion_depth: 0, light_bounces: 2}
)";

TEST(LightPath, VirtualLightsOfVirtualLightsByHand) {
  const Scene scene = loadSceneText(kTwoMirrors, "two-mirrors.yaml");
  const std::vector<RefFace> faces = findRefFaces(scene);
  ASSERT_EQ(faces.size(), 2u);
  bool over = true;
  const std::vector<LightPath> paths = lightPaths(scene, faces, 2, kMaxLightPaths, &over);
  EXPECT_FALSE(over);
  ASSERT_EQ(paths.size(), 4u);  // A, A B, B, B A: depth first, faces in scene order
  EXPECT_EQ(paths[0].faces, (std::vector<int>{0}));
  EXPECT_EQ(paths[1].faces, (std::vector<int>{0, 1}));
  EXPECT_EQ(paths[2].faces, (std::vector<int>{1}));
  EXPECT_EQ(paths[3].faces, (std::vector<int>{1, 0}));
  expectNear(paths[0].virtualLight(), DVec3(0, 0, -4));
  expectNear(paths[1].virtualLight(), DVec3(0, 0, 2));
  expectNear(paths[2].virtualLight(), DVec3(0, 0, 0));
  expectNear(paths[3].virtualLight(), DVec3(0, 0, -6));
  // A carried through B: the plane z = -3 reflected in z = -1 is z = 1.
  ASSERT_EQ(paths[1].apertures.size(), 2u);
  for (const DVec3& p : paths[1].apertures[0]) {
    EXPECT_NEAR(p.z, 1.0, 1e-6);
    EXPECT_NEAR(std::abs(p.x), 0.25, 1e-6);
    EXPECT_NEAR(std::abs(p.y), 0.25, 1e-6);
  }
  for (const DVec3& p : paths[1].apertures[1]) EXPECT_NEAR(p.z, -1.0, 1e-6);
  // A point between the mirrors carried along A, B: reflected in A, then B.
  expectNear(carryAlongPath(paths[1], faces, 0, DVec3(0.5, 0.25, -2.5)), DVec3(0.5, 0.25, 1.5));
  expectNear(carryAlongPath(paths[1], faces, 1, DVec3(0, 0, -2)), DVec3(0, 0, 0));
  EXPECT_FALSE(carryTurnsWinding(paths[1], faces, 0));  // two reflections
  EXPECT_TRUE(carryTurnsWinding(paths[1], faces, 1));
  // One bounce: the 1994 paper's virtual lights only.
  EXPECT_EQ(lightPaths(scene, faces, 1, kMaxLightPaths).size(), 2u);
}

TEST(LightPath, AFaceOutsideTheLightVolumeEndsThePath) {
  // A third mirror beside A, facing B: B's virtual light (0, 0, 0) reaches
  // it through B, but A's light (from (0, 0, -4) through A) reaches B only
  // within |X| <= 0.75 at z = -1 and goes on into B's volume from (0, 0, 2):
  // at z = -3 within |X| <= 1.25. C at x 2..3 is outside it, so A, B, C is
  // no path; B, C is (C lies in B's light volume from (0, 0, 0)).
  std::string text = kTwoMirrors;
  text.replace(text.find("render:"), 0,
               "  - {name: C, primitive: quad, translate: [2.5, 0, -3], scale: 1, material: mirror}\n");
  text.replace(text.find("light_bounces: 2"), 16, "light_bounces: 3");
  const Scene scene = loadSceneText(text, "three-mirrors.yaml");
  const std::vector<RefFace> faces = findRefFaces(scene);
  ASSERT_EQ(faces.size(), 3u);
  std::vector<std::vector<int>> found;
  for (const LightPath& p : lightPaths(scene, faces, 3, kMaxLightPaths)) found.push_back(p.faces);
  const auto has = [&](std::vector<int> f) { return std::find(found.begin(), found.end(), f) != found.end(); };
  EXPECT_TRUE(has({0, 1}));
  EXPECT_TRUE(has({1, 2}));
  EXPECT_FALSE(has({0, 1, 2}));
  EXPECT_TRUE(has({0, 1, 0}));  // A's light back onto A through B: A' lies inside the volume
}

TEST(LightPath, TheConstituentLightVolumesIntersectOnTheWall) {
  const Scene scene = loadSceneText(kTwoMirrors, "two-mirrors.yaml");
  GLContext gl(16, 16, indigoProfile());
  GLCommandStream stream(gl, false);
  std::optional<Framebuffer> afterVolumes;
  std::vector<Rgba8> beforeLight, afterLight;
  bool inPath = false;
  stream.onPassEnd([&](const std::string& label) {
    if (!afterVolumes && label.find("face_light_stencil(every face of the light path)") != std::string::npos)
      afterVolumes = gl.framebuffer(), inPath = true;
    if (inPath && label.find("make_all_shadows(CAN'T_INTERSECT") != std::string::npos)
      beforeLight = gl.framebuffer().colorData();
    if (inPath && label.find("lit by the virtual light") != std::string::npos)
      afterLight = gl.framebuffer().colorData(), inPath = false;
  });
  const RenderResult r = renderScene(scene, stream);
  EXPECT_EQ(r.plan.reflectedLights, 4);
  ASSERT_TRUE(afterVolumes);
  EXPECT_TRUE(test::stencilMatches(*afterVolumes, 0, 0, test::stencilPictureOf(16, 16, [](int x, int y) {
    const bool inA = x >= 5 && x <= 10 && y >= 5 && y <= 10;
    const bool inB = x >= 4 && x <= 11 && y >= 4 && y <= 11;
    return inA ? 192 : inB ? 193 : 194;
  })));
  // The twice-reflected light adds light inside both volumes only.
  ASSERT_EQ(afterLight.size(), 256u);
  for (std::size_t i = 0; i < 256; ++i) {
    const int x = static_cast<int>(i % 16), y = static_cast<int>(i / 16);
    const bool inside = x >= 5 && x <= 10 && y >= 5 && y <= 10;
    if (inside) EXPECT_GT(afterLight[i][0], beforeLight[i][0]) << x << "," << y;
    else EXPECT_EQ(afterLight[i], beforeLight[i]) << x << "," << y;
  }
}

TEST(LightPath, ColourIsTheProductOfTheFaces) {
  const Scene scene = loadSceneText(kTwoMirrors, "two-mirrors.yaml");
  const std::vector<ReflectedLight> lights = reflectedLights(scene, findRefFaces(scene));
  ASSERT_EQ(lights.size(), 4u);
  EXPECT_EQ(lights[0].virtualLight.color, Vec3(0.5f));
  EXPECT_EQ(lights[1].virtualLight.color, Vec3(0.25f));
  EXPECT_EQ(lights[1].lightVolumes.size(), 2u);
  EXPECT_EQ(lights[1].path, (std::vector<int>{0, 1}));
}

// 1997 eq. (7): per light n (d^2 + 3d) / 2 + 1 shadow generations for n
// faces each seen by the others at light depth d. Two facing mirrors have
// exactly n virtual lights per bounce, the path of j faces j + 1 volume
// sets (its own shadows and one per stretch): the equation holds exactly,
// and the volumes reflectedLights builds are the planner's count.
TEST(LightPath, HallOfMirrorsMeetsEquationSeven) {
  for (int d = 1; d <= 4; ++d) {
    const Scene scene = loadSceneFile(std::string(MPR_SOURCE_DIR) + "/scenes/hall_of_mirrors.yaml",
                                      {"render.light_bounces=" + std::to_string(d)});
    const RenderPlan p = planRender(scene);
    EXPECT_EQ(p.longestLightPath, d);
    EXPECT_EQ(static_cast<double>(p.shadowGenerations), p.paperEq7ShadowGenerations()) << d;
    std::uint64_t built = static_cast<std::uint64_t>(p.lights);
    for (const ReflectedLight& rl : reflectedLights(scene, findRefFaces(scene))) built += 1 + rl.path.size();
    EXPECT_EQ(built, p.shadowGenerations) << d;
  }
}

TEST(LightPath, TooManyPathsAreCounted) {
  // Two facing mirrors and 16 bounces: more than 20 paths; a limit of 20
  // stops the search and says so.
  const Scene scene = loadSceneText(kTwoMirrors, "two-mirrors.yaml");
  const std::vector<RefFace> faces = findRefFaces(scene);
  bool over = false;
  EXPECT_EQ(lightPaths(scene, faces, 16, 20, &over).size(), 20u);
  EXPECT_TRUE(over);
}

}  // namespace
}  // namespace mpr
