// Silhouettes from the half-edge connectivity, derived by hand for the unit
// box (makeBox: faces +z, -z, +x, -x, +y, -y, two triangles each, in that
// order; corners at +-0.5, counter-clockwise seen from outside).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "algorithms/silhouette.hpp"
#include "shadow_test_support.hpp"

namespace mpr {
namespace {

using test::key;
using test::PosKey;
using EdgeSet = std::set<std::pair<PosKey, PosKey>>;
constexpr float h = 0.5f;

EdgeSet edgesOf(const Silhouette& s) {
  EdgeSet out;
  for (const SilhouetteEdge& e : s.edges) out.insert({key(e.pa), key(e.pb)});
  return out;
}

// A closed loop given as its corners, each edge from one corner to the next.
EdgeSet loop(const std::vector<Vec3>& corners) {
  EdgeSet out;
  for (std::size_t i = 0; i < corners.size(); ++i) out.insert({key(corners[i]), key(corners[(i + 1) % corners.size()])});
  return out;
}

Silhouette silhouetteOf(const Mesh& m, Vec3 light) { return findSilhouette(m, buildMeshConnectivity(m), light); }

TEST(Silhouette, LightAboveTheBoxLightsTheTopOnly) {
  // Light over the centre, above the top (y = 3 > 0.5): only the +y face
  // has it strictly in front; the sides' planes (x, z = +-0.5) have it on
  // their inner side, the bottom faces away. The silhouette is the top
  // square, run against the top face's winding (-h,h,h) -> (h,h,h) ->
  // (h,h,-h) -> (-h,h,-h), i.e. clockwise seen from above.
  const Silhouette s = silhouetteOf(makeBox(), {0.0f, 3.0f, 0.0f});
  EXPECT_EQ(s.litTriangles, (std::vector<std::uint32_t>{8, 9}));
  EXPECT_EQ(s.unlitTriangles.size(), 10u);
  ASSERT_EQ(s.edges.size(), 4u);
  EXPECT_EQ(edgesOf(s), loop({{-h, h, -h}, {h, h, -h}, {h, h, h}, {-h, h, h}}));
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(s.boundaryEdgeCount, 0u);
  EXPECT_EQ(s.boundarySilhouetteEdges, 0u);
}

TEST(Silhouette, LightOnTheCornerDiagonalGivesTheHexagon) {
  // Light at (2, 2, 2): +x, +y, +z lit. The silhouette is the six edges
  // between them and -x, -y, -z: the hexagon avoiding the corners
  // (h,h,h) and (-h,-h,-h). Lit windings give (-h,-h,h) -> (h,-h,h) ->
  // (h,-h,-h) -> (h,h,-h) -> (-h,h,-h) -> (-h,h,h) -> back; the silhouette
  // runs the other way.
  const Silhouette s = silhouetteOf(makeBox(), {2.0f, 2.0f, 2.0f});
  EXPECT_EQ(s.litTriangles, (std::vector<std::uint32_t>{0, 1, 4, 5, 8, 9}));
  ASSERT_EQ(s.edges.size(), 6u);
  EXPECT_EQ(edgesOf(s), loop({{-h, -h, h}, {-h, h, h}, {-h, h, -h}, {h, h, -h}, {h, -h, -h}, {h, -h, h}}));
}

TEST(Silhouette, LightInAFacePlaneLeavesThatFaceUnlit) {
  // Light at (0, 0.5, 3): exactly in the top face's plane. Top unlit
  // (decided exactly: the offset is zero), +z lit; the silhouette is the
  // +z square.
  const Silhouette s = silhouetteOf(makeBox(), {0.0f, h, 3.0f});
  EXPECT_EQ(s.litTriangles, (std::vector<std::uint32_t>{0, 1}));
  ASSERT_EQ(s.edges.size(), 4u);
  EXPECT_EQ(edgesOf(s), loop({{-h, -h, h}, {-h, h, h}, {h, h, h}, {h, -h, h}}));
  EXPECT_FALSE(triangleFacesLight({-h, h, h}, {h, h, h}, {h, h, -h}, {0.0f, h, 3.0f}));
  EXPECT_FALSE(triangleFacesLight({-h, h, h}, {h, h, h}, {h, h, -h}, {0.0f, h, -7.25f}));
}

TEST(Silhouette, LightOnACornerLightsNothing) {
  // Three faces have the light in their plane, three behind it.
  const Silhouette s = silhouetteOf(makeBox(), {h, h, h});
  EXPECT_TRUE(s.litTriangles.empty());
  EXPECT_EQ(s.unlitTriangles.size(), 12u);
  EXPECT_TRUE(s.edges.empty());
}

TEST(Silhouette, LightInsideTheBoxLightsNothing) {
  const Silhouette s = silhouetteOf(makeBox(), {0.1f, -0.2f, 0.3f});
  EXPECT_TRUE(s.litTriangles.empty());
  EXPECT_TRUE(s.edges.empty());
}

TEST(Silhouette, ZeroAreaTrianglesAreNeitherLitNorUnlit) {
  Mesh box = makeBox();
  box.triangles.push_back({8, 8, 9});
  const auto n = static_cast<std::uint32_t>(box.positions.size());
  box.positions.push_back({-h, h, h});
  box.positions.push_back({0.0f, h, h});
  box.positions.push_back({h, h, h});
  box.triangles.push_back({n, n + 1, n + 2});
  EXPECT_FALSE(triangleFacesLight(box.positions[n], box.positions[n + 1], box.positions[n + 2], {0.0f, 3.0f, 1.0f}));
  const Silhouette s = silhouetteOf(box, {0.0f, 3.0f, 0.0f});
  EXPECT_EQ(s.litTriangles.size() + s.unlitTriangles.size(), 12u);
  EXPECT_EQ(edgesOf(s), loop({{-h, h, -h}, {h, h, -h}, {h, h, h}, {-h, h, h}}));
  EXPECT_TRUE(s.closed);
}

TEST(Silhouette, OpenQuadUsesItsBoundaryEdges) {
  // One face (two triangles), lit from the front: its four boundary edges
  // are the silhouette, the mesh is open.
  const Silhouette s = silhouetteOf(makeQuad(), {0.2f, 0.1f, 2.0f});
  EXPECT_EQ(s.litTriangles.size(), 2u);
  EXPECT_TRUE(s.unlitTriangles.empty());
  ASSERT_EQ(s.edges.size(), 4u);
  EXPECT_EQ(s.boundarySilhouetteEdges, 4u);
  EXPECT_EQ(s.boundaryEdgeCount, 4u);
  EXPECT_FALSE(s.closed);
  for (const SilhouetteEdge& e : s.edges) EXPECT_TRUE(e.boundary);
  EXPECT_EQ(edgesOf(s), loop({{-h, -h, 0}, {-h, h, 0}, {h, h, 0}, {h, -h, 0}}));
  // From behind, nothing is lit: an open mesh casts no shadow from its back.
  const Silhouette back = silhouetteOf(makeQuad(), {0.2f, 0.1f, -2.0f});
  EXPECT_TRUE(back.litTriangles.empty());
  EXPECT_TRUE(back.edges.empty());
  EXPECT_EQ(back.boundaryEdgeCount, 4u);
}

TEST(Silhouette, SingleTriangleHasThreeEdges) {
  Mesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  const Silhouette s = silhouetteOf(tri, {0.2f, 0.2f, 1.0f});
  EXPECT_EQ(s.litTriangles.size(), 1u);
  EXPECT_EQ(edgesOf(s), loop({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}));
}

// In/out degree of every silhouette vertex (weld ids).
std::map<std::uint32_t, std::pair<int, int>> degrees(const Silhouette& s) {
  std::map<std::uint32_t, std::pair<int, int>> d;
  for (const SilhouetteEdge& e : s.edges) d[e.a].second += 1, d[e.b].first += 1;
  return d;
}

TEST(Silhouette, SphereSilhouetteIsOneLoop) {
  const Mesh sphere = makeSphere(32, 16);
  const MeshConnectivity c = buildMeshConnectivity(sphere);
  ASSERT_TRUE(c.closed);
  for (const Vec3 light : {Vec3(3.1f, 2.3f, -1.7f), Vec3(0.0f, 5.0f, 0.0f), Vec3(-1.3f, -0.4f, 1.9f)}) {
    const Silhouette s = findSilhouette(sphere, c, light);
    ASSERT_GE(s.edges.size(), 8u);
    // Each vertex: one edge in, one out.
    std::map<std::uint32_t, std::uint32_t> next;
    for (const auto& [v, io] : degrees(s)) {
      EXPECT_EQ(io.first, 1) << "vertex " << v;
      EXPECT_EQ(io.second, 1) << "vertex " << v;
    }
    for (const SilhouetteEdge& e : s.edges) next[e.a] = e.b;
    // Following the edges from any vertex visits all of them once.
    std::uint32_t v = s.edges[0].a;
    std::size_t steps = 0;
    do {
      v = next.at(v);
      ++steps;
    } while (v != s.edges[0].a && steps <= s.edges.size());
    EXPECT_EQ(steps, s.edges.size());
    // Every silhouette edge separates a lit and an unlit triangle.
    EXPECT_EQ(s.boundarySilhouetteEdges, 0u);
    EXPECT_EQ(s.litTriangles.size() + s.unlitTriangles.size(), sphere.triangles.size());
  }
}

TEST(Silhouette, EdgesBetweenTwoLitFacesOfTouchingBoxesCancel) {
  // Box B sits on box A's edge x = 0.5, y = 0.5. From (0.3, 5, 0.1) A's
  // top and B's -x face are both lit and meet at that edge, forming a
  // concave crease: not a silhouette edge of the union, although each box
  // alone would have one there (in opposite directions).
  const Mesh two = test::concat(test::boxAt({0, 0, 0}), test::boxAt({1, 1, 0}));
  const Silhouette s = silhouetteOf(two, {0.3f, 5.0f, 0.1f});
  for (const SilhouetteEdge& e : s.edges)
    EXPECT_FALSE(e.pa.x == h && e.pa.y == h && e.pb.x == h && e.pb.y == h) << "shared edge kept";
  for (const auto& [v, io] : degrees(s)) EXPECT_EQ(io.first, io.second) << "vertex " << v;
  EXPECT_TRUE(s.closed);
}

}  // namespace
}  // namespace mpr
