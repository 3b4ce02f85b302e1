// render.tessellation: lit triangles split k x k without cracks.
#include "scene/tessellation.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "scene/scene_loader.hpp"

namespace mpr {
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

}  // namespace
}  // namespace mpr
