#include "algorithms/silhouette.hpp"

#include <algorithm>
#include <map>

#include "algorithms/plane.hpp"

namespace mpr {

bool triangleFacesLight(Vec3 a, Vec3 b, Vec3 c, Vec3 light) {
  // The front normal (b - a) x (c - a) against the light's offset from a.
  // Differences of floats of similar magnitude are exact in double, so a
  // light exactly in the plane of an axis-aligned face gives exactly zero
  // (unlit) rather than a rounding-dependent sign.
  const DVec3 da(a), n = glm::cross(DVec3(b) - da, DVec3(c) - da);
  return glm::dot(n, DVec3(light) - da) > 0.0;  // NaN compares false: unlit
}

Silhouette findSilhouette(const Mesh& mesh, const MeshConnectivity& conn, Vec3 light) {
  Silhouette s;
  s.closed = conn.closed;
  s.boundaryEdgeCount = conn.boundaryEdges.size();
  const TriMesh& tm = conn.mesh;

  std::vector<bool> lit(tm.n_faces(), false);
  for (std::size_t f = 0; f < tm.n_faces(); ++f) {
    const std::uint32_t t = conn.triangleOfFace[f];
    const auto& tri = mesh.triangles[t];
    lit[f] = triangleFacesLight(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]], light);
    (lit[f] ? s.litTriangles : s.unlitTriangles).push_back(t);
  }
  auto litFace = [&](OpenMesh::FaceHandle f) { return f.is_valid() && lit[static_cast<std::size_t>(f.idx())]; };

  // Candidates: a halfedge of a lit face whose opposite side is unlit or
  // open. Directed against the lit face's winding (see SilhouetteEdge).
  std::vector<WeldedEdge> candidates;
  for (const auto eh : tm.edges()) {
    for (int side = 0; side < 2; ++side) {
      const auto h = tm.halfedge_handle(eh, static_cast<unsigned>(side));
      if (!litFace(tm.face_handle(h)) || litFace(tm.face_handle(tm.opposite_halfedge_handle(h)))) continue;
      candidates.push_back({conn.weldOfVertex[static_cast<std::size_t>(tm.to_vertex_handle(h).idx())],
                            conn.weldOfVertex[static_cast<std::size_t>(tm.from_vertex_handle(h).idx())]});
    }
  }

  // Net count per welded edge: where a detached (non-manifold) lit triangle
  // leaves an edge open in the TriMesh that another lit triangle closes
  // with the opposite direction, the two cancel, as the surfaces they stand
  // for would.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;
  for (const WeldedEdge& e : candidates) net[{std::min(e.a, e.b), std::max(e.a, e.b)}] += e.a < e.b ? 1 : -1;
  for (const WeldedEdge& e : candidates) {
    int& n = net[{std::min(e.a, e.b), std::max(e.a, e.b)}];
    const int dir = e.a < e.b ? 1 : -1;
    if (n * dir <= 0) continue;  // cancelled, or already emitted as often as it counts
    n -= dir;
    SilhouetteEdge out;
    out.a = e.a;
    out.b = e.b;
    out.pa = conn.weldedPositions[e.a];
    out.pb = conn.weldedPositions[e.b];
    out.boundary = conn.uses(e.a, e.b).total() == 1;
    s.boundarySilhouetteEdges += out.boundary ? 1 : 0;
    s.edges.push_back(out);
  }
  return s;
}

}  // namespace mpr
