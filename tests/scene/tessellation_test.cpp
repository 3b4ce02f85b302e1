// render.tessellation: lit triangles split k x k without cracks.
#include "scene/tessellation.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::tessellation_test {
namespace {

const char* kRoom = R"(
lights: [{position: [0, 3, 0]}]
materials: {m: {kind: mirror}, d: {diffuse: [0.5, 0.5, 0.5]}}
objects:
  - {name: wall, primitive: quad, scale: [4, 2, 1], material: d}
  - {name: mirror, primitive: quad, translate: [0, 0, 1], material: m}
  - {name: box, primitive: box, material: d}
)";

// The wall's longest edge is its diagonal, sqrt(4^2 + 2^2) = 4.47; edges of
// at most 1 need k = 5: each of its 2 triangles becomes 25. The box's
// longest edge is a side's diagonal, 1.414: k = 2, 12 x 4 = 48. The mirror
// keeps its 2 triangles and its face.
TEST(Tessellation, SplitsLitObjectsOnly) {
  Scene s = loadSceneText(kRoom, "s.yaml");
  tessellateLitObjects(s, 1.0f);
  EXPECT_EQ(s.objects[0].mesh.triangles.size(), 50u);
  EXPECT_EQ(s.objects[1].mesh.triangles.size(), 2u);
  EXPECT_EQ(s.objects[1].mesh.faces.size(), 1u);
  EXPECT_EQ(s.objects[2].mesh.triangles.size(), 48u);
  for (const SceneObject& o : s.objects)
    for (const auto& t : o.mesh.triangles)
      for (int e = 0; e < 3; ++e)
        EXPECT_LE(glm::length(o.mesh.positions[t[e]] - o.mesh.positions[t[(e + 1) % 3]]), o.name == "mirror" ? 2.0f : 1.0f);
}

// Every edge of `m` used once each way after welding positions exactly.
bool closedAfterWelding(const Mesh& m) {
  std::map<std::tuple<float, float, float>, int> weld;
  std::vector<int> id;
  for (const Vec3& p : m.positions) id.push_back(weld.emplace(std::make_tuple(p.x, p.y, p.z), weld.size()).first->second);
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e) ++uses[{id[t[e]], id[t[(e + 1) % 3]]}];
  for (const auto& [edge, n] : uses)
    if (n != 1 || uses.count({edge.second, edge.first}) != 1) return false;
  return true;
}

// No cracks: every edge of the split box is used by exactly two triangles,
// once in each direction, after the positions are welded exactly (a
// T-junction or a point computed differently on the two sides of an edge
// would leave an edge used once).
TEST(Tessellation, SharedEdgesStayShared) {
  Scene s = loadSceneText(kRoom, "s.yaml");
  tessellateLitObjects(s, 0.3f);
  const Mesh& m = s.objects[2].mesh;
  EXPECT_TRUE(closedAfterWelding(m));
  // k = ceil(1.414 / 0.3) = 5: 12 x 25 triangles.
  EXPECT_EQ(m.triangles.size(), 300u);
}

TEST(Tessellation, ZeroLeavesTheSceneAlone) {
  Scene s = loadSceneText(kRoom, "s.yaml");
  const std::size_t before = s.triangleCount();
  tessellateLitObjects(s, 0.0f);
  EXPECT_EQ(s.triangleCount(), before);
  EXPECT_EQ(loadSceneText(kRoom, "s.yaml", {"render.tessellation=0.25"}).render.tessellation, 0.25f);
  EXPECT_THROW(loadSceneText(kRoom, "s.yaml", {"render.tessellation=-1"}), SceneError);
}

// The count the loader holds to the budget is the count the split makes.
TEST(Tessellation, CountPredictsTheSplit) {
  for (const float edge : {1.0f, 0.3f, 0.01f, 0.0f, 1e30f}) {
    Scene s = loadSceneText(kRoom, "s.yaml");
    const std::uint64_t predicted = tessellatedTriangleCount(s, edge);
    tessellateLitObjects(s, edge);
    EXPECT_EQ(predicted, s.triangleCount()) << edge;
  }
}

// Issue 15: a tessellation that would take the scene past its triangle
// budget is refused where it is written (in the file or by --set).
TEST(Tessellation, PastTheSceneBudgetIsALocatedError) {
  std::string text = "render: {tessellation: 0.001}\nobjects:\n  - &b {primitive: box}\n";
  for (int i = 1; i < 520; ++i) text += "  - *b\n";  // 520 x 12 x 64^2 = 25 559 040 > 24 Mi
  try {
    loadSceneText(text, "t.yaml");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("t.yaml:1:24: render.tessellation 0.001 would split the lit faces into 25559040"),
              std::string::npos) << e.what();
  }
  try {
    loadSceneText(text, "t.yaml", {"render.tessellation=0.01"});
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--set render.tessellation=0.01:1:1:", 0), 0u) << e.what();
  }
  // 511 boxes fit: 25 116 672 triangles.
  std::string fits = "render: {tessellation: 0.001}\nobjects:\n  - &b {primitive: box}\n";
  for (int i = 1; i < 511; ++i) fits += "  - *b\n";
  EXPECT_EQ(tessellatedTriangleCount(loadSceneText(fits, "f.yaml"), 0.001f), 25'116'672u);
}

}  // namespace
}  // namespace mpr::tessellation_test

namespace mpr::tessellation_test {
namespace {

// Issue 43: a corner of a split edge was computed as u + (v - u) * 1, which
// need not round to v: the default scene's cube (turned 25 degrees) opened
// at its corners, and its shadow volume was counted as an open mesh's.
TEST(Tessellation, ATurnedBoxStaysClosed) {
  Scene s = loadSceneText(R"(
lights: [{position: [1.5, 3.4, 2.5]}]
objects:
  - {name: cube, primitive: box, translate: [-1.0, 0.5, 0.2], rotate: [25, 0, 1, 0]}
)", "s.yaml");
  for (const float edge : {1.0f, 0.5f, 0.3f, 0.1f}) {
    Scene t = s;
    tessellateLitObjects(t, edge);
    EXPECT_GT(t.objects[0].mesh.triangles.size(), 12u) << edge;
    EXPECT_TRUE(closedAfterWelding(t.objects[0].mesh)) << edge;
  }
}

// render.tessellation auto (the default): an object's longest edge at most
// a quarter of its bounding box's distance to the nearest light. An 8 x 8
// quad (diagonal 11.31) with the first light 4 above it (the second 8.06
// away): 11.31 / 4 / 0.25 = 11.3, k = 12, 2 x 144 triangles; the second
// light 0.5 above a unit box (side diagonal 1.414): 1.414 / 0.5 / 0.25 =
// 11.3, k = 12 too; a box 12.5 from it: 1.414 / 12.5 / 0.25 = 0.45, kept as
// it is. Scaling the whole scene changes none of it.
TEST(Tessellation, AutoSplitsByTheDistanceToTheNearestLight) {
  const char* text = R"(
lights: [{position: [0, 4, 0]}, {position: [0, 1, -12]}]
objects:
  - {name: floor, primitive: quad, rotate: [-90, 1, 0, 0], scale: [8, 8, 1]}
  - {name: near box, primitive: box, translate: [0, 0, -12]}
  - {name: far box, primitive: box, translate: [0, 0, -25]}
)";
  Scene s = loadSceneText(text, "s.yaml");
  EXPECT_EQ(s.render.tessellation, kAutoTessellation);
  Scene scaled = s;
  for (PointLight& l : scaled.lights) l.position *= 1000.0f;
  for (SceneObject& o : scaled.objects)
    for (Vec3& p : o.mesh.positions) p *= 1000.0f;
  for (Scene* t : {&s, &scaled}) {
    tessellateLitObjects(*t, kAutoTessellation);
    EXPECT_EQ(t->objects[0].mesh.triangles.size(), 288u);
    EXPECT_EQ(t->objects[1].mesh.triangles.size(), 12u * 144u);
    EXPECT_EQ(t->objects[2].mesh.triangles.size(), 12u);
  }
  EXPECT_EQ(loadSceneText(std::string(text) + "render: {tessellation: auto}\n", "s.yaml").render.tessellation,
            kAutoTessellation);
  EXPECT_EQ(loadSceneText(std::string(text) + "render: {tessellation: 0}\n", "s.yaml").render.tessellation, 0.0f);
}

}  // namespace
}  // namespace mpr::tessellation_test
