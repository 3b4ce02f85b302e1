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

// No cracks: every edge of the split box is used by exactly two triangles,
// once in each direction, after the positions are welded exactly (a
// T-junction or a point computed differently on the two sides of an edge
// would leave an edge used once).
TEST(Tessellation, SharedEdgesStayShared) {
  Scene s = loadSceneText(kRoom, "s.yaml");
  tessellateLitObjects(s, 0.3f);
  const Mesh& m = s.objects[2].mesh;
  std::map<std::tuple<float, float, float>, int> weld;
  std::vector<int> id;
  for (const Vec3& p : m.positions) id.push_back(weld.emplace(std::make_tuple(p.x, p.y, p.z), weld.size()).first->second);
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e) ++uses[{id[t[e]], id[t[(e + 1) % 3]]}];
  for (const auto& [edge, n] : uses) {
    EXPECT_EQ(n, 1) << edge.first << "-" << edge.second;
    EXPECT_EQ(uses.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
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
