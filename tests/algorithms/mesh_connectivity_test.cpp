// Welding scene meshes into OpenMesh half-edge connectivity: exact-position
// welding, boundary and non-manifold reports, and no triangle lost on the
// way (non-manifold ones go in detached, non-manifold vertices are split).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

#include "algorithms/mesh_connectivity.hpp"
#include "shadow_test_support.hpp"

namespace mpr {
namespace {

using test::boxAt;
using test::concat;

// Every halfedge of the TriMesh with a face has a valid opposite, and the
// face's vertices are the welded triangle's, in order up to rotation.
void expectFacesMatchTriangles(const Mesh& m, const MeshConnectivity& c) {
  for (std::size_t f = 0; f < c.mesh.n_faces(); ++f) {
    const auto& tri = m.triangles[c.triangleOfFace[f]];
    std::vector<std::uint32_t> got;
    for (const auto vh : c.mesh.fv_range(OpenMesh::FaceHandle(static_cast<int>(f))))
      got.push_back(c.weldOfVertex[static_cast<std::size_t>(vh.idx())]);
    ASSERT_EQ(got.size(), 3u);
    const std::vector<std::uint32_t> want = {c.weldOfPosition[tri[0]], c.weldOfPosition[tri[1]], c.weldOfPosition[tri[2]]};
    const bool rotated = got == want || got == std::vector<std::uint32_t>{want[1], want[2], want[0]} ||
                         got == std::vector<std::uint32_t>{want[2], want[0], want[1]};
    EXPECT_TRUE(rotated) << "face " << f;
    EXPECT_EQ(c.faceOfTriangle[c.triangleOfFace[f]], static_cast<int>(f));
  }
}

TEST(MeshConnectivity, UnitCubeFrom24VerticesWeldsClosed) {
  const Mesh box = makeBox();
  ASSERT_EQ(box.positions.size(), 24u);
  const MeshConnectivity c = buildMeshConnectivity(box);
  EXPECT_EQ(c.weldedPositions.size(), 8u);
  EXPECT_EQ(c.mesh.n_vertices(), 8u);
  EXPECT_EQ(c.mesh.n_faces(), 12u);
  EXPECT_EQ(c.triangleCount(), 12u);
  EXPECT_EQ(c.mesh.n_edges(), 18u);
  EXPECT_EQ(c.edgeCount(), 18u);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.manifold());
  EXPECT_TRUE(c.boundaryEdges.empty());
  EXPECT_TRUE(c.degenerateTriangles.empty());
  EXPECT_TRUE(c.detachedTriangles.empty());
  for (const auto eh : c.mesh.edges()) EXPECT_FALSE(c.mesh.is_boundary(eh));
  // Euler characteristic of a sphere.
  EXPECT_EQ(static_cast<long>(c.mesh.n_vertices()) - static_cast<long>(c.mesh.n_edges()) +
                static_cast<long>(c.mesh.n_faces()),
            2);
  expectFacesMatchTriangles(box, c);
}

TEST(MeshConnectivity, TransformedBoxStillWelds) {
  // Equal floats stay equal under one transform, so a placed box welds too.
  Mesh box = makeBox();
  transformMesh(box, glm::rotate(glm::translate(Mat4(1.0f), Vec3(0.3f, 1.7f, -2.1f)), 0.7f, Vec3(0.2f, 1.0f, 0.4f)));
  const MeshConnectivity c = buildMeshConnectivity(box);
  EXPECT_EQ(c.weldedPositions.size(), 8u);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.edgeCount(), 18u);
}

TEST(MeshConnectivity, QuadIsOpenWithFourDirectedBoundaryEdges) {
  const Mesh quad = makeQuad();
  const MeshConnectivity c = buildMeshConnectivity(quad);
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.mesh.n_faces(), 2u);
  EXPECT_EQ(c.edgeCount(), 5u);
  ASSERT_EQ(c.boundaryEdges.size(), 4u);
  // Directed as the triangles run (counter-clockwise seen from +z): one
  // loop 0 -> 1 -> 2 -> 3 -> 0 over the quad's corners.
  std::set<std::pair<std::uint32_t, std::uint32_t>> got, want;
  for (const WeldedEdge& e : c.boundaryEdges) got.insert({e.a, e.b});
  for (std::uint32_t i = 0; i < 4; ++i) want.insert({c.weldOfPosition[i], c.weldOfPosition[(i + 1) % 4]});
  EXPECT_EQ(got, want);
  std::size_t boundaryHalfedges = 0;
  for (const auto eh : c.mesh.edges()) boundaryHalfedges += c.mesh.is_boundary(eh) ? 1 : 0;
  EXPECT_EQ(boundaryHalfedges, 4u);
}

TEST(MeshConnectivity, ZeroAreaTrianglesAreLeftOut) {
  Mesh box = makeBox();
  box.triangles.push_back({0, 0, 1});  // two corners the same
  const auto n = static_cast<std::uint32_t>(box.positions.size());
  box.positions.push_back({-0.5f, -0.5f, 0.5f});
  box.positions.push_back({0.0f, -0.5f, 0.5f});
  box.positions.push_back({0.5f, -0.5f, 0.5f});
  box.triangles.push_back({n, n + 1, n + 2});  // collinear, distinct corners (on a box edge)
  const MeshConnectivity c = buildMeshConnectivity(box);
  EXPECT_EQ(c.degenerateTriangles, (std::vector<std::uint32_t>{12, 13}));
  EXPECT_EQ(c.faceOfTriangle[12], -1);
  EXPECT_EQ(c.faceOfTriangle[13], -1);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.manifold());
  EXPECT_EQ(c.mesh.n_faces(), 12u);
  EXPECT_EQ(c.edgeCount(), 18u);
}

TEST(MeshConnectivity, NonFiniteCornerIsDegenerateNotAWeldKey) {
  Mesh quad = makeQuad();
  quad.positions[2].x = std::numeric_limits<float>::quiet_NaN();
  const MeshConnectivity c = buildMeshConnectivity(quad);
  EXPECT_EQ(c.degenerateTriangles.size(), 2u);  // both triangles use position 2
  EXPECT_EQ(c.mesh.n_faces(), 0u);
}

TEST(MeshConnectivity, ThreeTrianglesOnOneEdgeAreNonManifoldButKept) {
  Mesh fin;
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0.2f}, {0.5f, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshConnectivity c = buildMeshConnectivity(fin);
  ASSERT_EQ(c.nonManifoldEdges.size(), 1u);
  EXPECT_EQ(c.nonManifoldEdges[0], (WeldedEdge{0, 1}));
  EXPECT_EQ(c.detachedTriangles, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(c.mesh.n_faces(), 3u);
  EXPECT_EQ(c.mesh.n_vertices(), 9u);  // detached: three own vertices each
  EXPECT_FALSE(c.closed);
  EXPECT_FALSE(c.manifold());
  expectFacesMatchTriangles(fin, c);
}

TEST(MeshConnectivity, FlippedTriangleBreaksClosure) {
  Mesh box = makeBox();
  std::swap(box.triangles[0][1], box.triangles[0][2]);
  const MeshConnectivity c = buildMeshConnectivity(box);
  EXPECT_FALSE(c.closed);
  // Its two outer edges are now used twice in one direction; its diagonal
  // (shared with triangle 1, also flipped relative to it) likewise.
  EXPECT_EQ(c.nonManifoldEdges.size(), 3u);
  EXPECT_EQ(c.mesh.n_faces(), 12u);
  EXPECT_TRUE(std::find(c.detachedTriangles.begin(), c.detachedTriangles.end(), 0u) != c.detachedTriangles.end());
}

TEST(MeshConnectivity, TwoBoxesSharingAnEdgeAreClosedButNonManifold) {
  // Box B touches box A along the edge x = 0.5, y = 0.5.
  const Mesh two = concat(boxAt({0, 0, 0}), boxAt({1, 1, 0}));
  const MeshConnectivity c = buildMeshConnectivity(two);
  EXPECT_TRUE(c.closed);  // every welded edge balanced
  EXPECT_EQ(c.nonManifoldEdges.size(), 1u);
  EXPECT_EQ(c.detachedTriangles.size(), 4u);  // two per box use that edge
  EXPECT_EQ(c.mesh.n_faces(), 24u);
  expectFacesMatchTriangles(two, c);
}

TEST(MeshConnectivity, TetrahedraTouchingAtATipSplitTheVertex) {
  // Two closed tetrahedra sharing only the apex (0, 0, 0).
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  auto tet = [&](std::uint32_t o, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    // Outward for the tetrahedron o, a, b, c with o at the right-handed corner.
    m.triangles.push_back({o, b, a});
    m.triangles.push_back({o, c, b});
    m.triangles.push_back({o, a, c});
    m.triangles.push_back({a, b, c});
  };
  tet(0, 1, 2, 3);
  tet(0, 4, 6, 5);
  const MeshConnectivity c = buildMeshConnectivity(m);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.nonManifoldEdges.empty());
  EXPECT_EQ(c.splitVertices, 1u);
  EXPECT_EQ(c.weldedPositions.size(), 7u);
  EXPECT_EQ(c.mesh.n_vertices(), 8u);
  EXPECT_EQ(c.mesh.n_faces(), 8u);
  EXPECT_TRUE(c.detachedTriangles.empty());
  for (const auto eh : c.mesh.edges()) EXPECT_FALSE(c.mesh.is_boundary(eh));
  expectFacesMatchTriangles(m, c);
}

TEST(MeshConnectivity, SphereWeldsClosedInAnyTriangleOrder) {
  Mesh sphere = makeSphere(24, 12);
  const MeshConnectivity c = buildMeshConnectivity(sphere);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.manifold());
  EXPECT_EQ(c.weldedPositions.size(), 24u * 11u + 2u);
  // OpenMesh must accept every triangle however the fans are assembled.
  test::Random rng(7);
  for (std::size_t i = sphere.triangles.size(); i > 1; --i)
    std::swap(sphere.triangles[i - 1],
              sphere.triangles[static_cast<std::size_t>(rng.uniform(0.0, static_cast<double>(i)))]);
  const MeshConnectivity d = buildMeshConnectivity(sphere);
  EXPECT_TRUE(d.closed);
  EXPECT_TRUE(d.detachedTriangles.empty());
  EXPECT_EQ(d.mesh.n_faces(), sphere.triangles.size());
  for (const auto eh : d.mesh.edges()) EXPECT_FALSE(d.mesh.is_boundary(eh));
  expectFacesMatchTriangles(sphere, d);
}

TEST(MeshConnectivity, PrimitiveSphereAndCylinderWeldClosed) {
  // Their seams and poles repeat bit-equal points (primitives.cpp), so
  // exact welding closes them.
  for (const auto& [slices, stacks] : {std::pair{32, 16}, std::pair{3, 2}, std::pair{7, 5}}) {
    const MeshConnectivity c = buildMeshConnectivity(makeSphere(slices, stacks));
    EXPECT_TRUE(c.closed) << slices << "x" << stacks;
    EXPECT_TRUE(c.manifold());
    EXPECT_EQ(c.weldedPositions.size(), static_cast<std::size_t>(slices * (stacks - 1) + 2));
    EXPECT_EQ(static_cast<long>(c.mesh.n_vertices()) - static_cast<long>(c.mesh.n_edges()) +
                  static_cast<long>(c.mesh.n_faces()),
              2);
  }
  const MeshConnectivity cyl = buildMeshConnectivity(makeCylinder(32));
  EXPECT_TRUE(cyl.closed);
  EXPECT_TRUE(cyl.manifold());
  EXPECT_EQ(cyl.weldedPositions.size(), 64u);
}

TEST(MeshConnectivity, BadIndexThrows) {
  Mesh m = makeQuad();
  m.triangles.push_back({0, 1, 99});
  EXPECT_THROW(buildMeshConnectivity(m), std::invalid_argument);
}

TEST(MeshConnectivity, EdgeUsesAreOrientedByTheQuery) {
  const Mesh quad = makeQuad();
  const MeshConnectivity c = buildMeshConnectivity(quad);
  const std::uint32_t a = c.weldOfPosition[0], b = c.weldOfPosition[1];
  EXPECT_EQ(c.uses(a, b).forward, 1);
  EXPECT_EQ(c.uses(a, b).backward, 0);
  EXPECT_EQ(c.uses(b, a).forward, 0);
  EXPECT_EQ(c.uses(b, a).backward, 1);
  EXPECT_EQ(c.uses(a, 77).total(), 0);
}

}  // namespace
}  // namespace mpr
