// Subdivided primitives: grids of cells sharing corners, every side one
// polygon, shared box edges bit for bit the same on both sides.
#include "scene/primitives.hpp"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::primitives_test {
namespace {

Vec3 geometricNormal(const Mesh& m, const std::array<std::uint32_t, 3>& t) {
  return glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
}

// A 4 x 4 quad: 5 x 5 corners, 32 triangles facing +z, one face: the square.
TEST(Primitives, SubdividedQuadIsAGridAndOnePolygon) {
  const Mesh m = makeQuad(4);
  EXPECT_EQ(m.positions.size(), 25u);
  EXPECT_EQ(m.triangles.size(), 32u);
  for (const auto& t : m.triangles) EXPECT_GT(geometricNormal(m, t).z, 0.0f);
  ASSERT_EQ(m.faces.size(), 1u);
  const std::vector<Vec3> corners = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(m.positions[m.faces[0][k]], corners[k]) << k;
  // The cell corners are -0.5 + k/4: exact binary fractions.
  EXPECT_EQ(m.positions[1].x, -0.25f);
  EXPECT_EQ(m.positions[6].y, -0.25f);
}

// A box of 3 cells a side: its surface holds (3+1)^3 - (3-1)^3 = 56 lattice
// points; every side computes its edge points alike, so 6 x 16 = 96 grid
// vertices collapse to exactly 56 distinct positions.
TEST(Primitives, SubdividedBoxSharesItsEdgesExactly) {
  const Mesh m = makeBox(3);
  EXPECT_EQ(m.positions.size(), 96u);
  EXPECT_EQ(m.triangles.size(), 6u * 18u);
  std::set<std::tuple<float, float, float>> distinct;
  for (const Vec3& p : m.positions) distinct.insert({p.x, p.y, p.z});
  EXPECT_EQ(distinct.size(), 56u);
  // Each triangle faces outwards: along its vertices' (side) normal.
  for (const auto& t : m.triangles) EXPECT_GT(glm::dot(geometricNormal(m, t), m.normals[t[0]]), 0.0f);
  EXPECT_EQ(m.faces.size(), 6u);
}

TEST(Primitives, OneDivisionIsTheUnsubdividedMesh) {
  const Mesh a = makeBox(), b = makeBox(1);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles.size(), 12u);
  EXPECT_EQ(makeQuad(1).positions, makeQuad().positions);
}

// A plane of 8 x 8 cells is one polygon: a mirror plane is one mirror.
TEST(Primitives, APlaneIsOnePolygon) {
  const Mesh m = makePlane(8);
  EXPECT_EQ(m.triangles.size(), 128u);
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.positions[m.faces[0][0]], Vec3(-0.5f, 0.0f, 0.5f));
  EXPECT_EQ(m.positions[m.faces[0][2]].x, m.positions[m.faces[0][1]].x);
}

TEST(Primitives, TheLoaderSubdividesBoxesAndQuads) {
  const std::string head = "lights: [{position: [0, 3, 0]}]\nobjects:\n";
  const Scene s = loadSceneText(head + "  - {primitive: box, subdivisions: 2}\n  - {primitive: quad, subdivisions: 3}\n",
                                "s.yaml");
  EXPECT_EQ(s.objects[0].mesh.triangles.size(), 48u);
  EXPECT_EQ(s.objects[1].mesh.triangles.size(), 18u);
  try {
    loadSceneText(head + "  - {name: q, primitive: quad, subdivisions: 1025}\n", "s.yaml");
    FAIL() << "a 1025-division quad was accepted";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "s.yaml:3:46: object 'q' subdivisions must be at most 1024 for a quad (its cells grow with the square), not 1025");
  }
}

}  // namespace
}  // namespace mpr::primitives_test
