#include "algorithms/mesh_connectivity.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "algorithms/plane.hpp"

namespace mpr {
namespace {

using Key = std::pair<std::uint32_t, std::uint32_t>;

Key undirected(std::uint32_t a, std::uint32_t b) { return a < b ? Key{a, b} : Key{b, a}; }

bool finite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Union-find over triangle corners (3 t + k), to group the corners at one
// welded vertex into fans.
struct Corners {
  std::vector<std::uint32_t> parent;
  explicit Corners(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  // The smaller root wins, so the result does not depend on call order.
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

EdgeUse MeshConnectivity::uses(std::uint32_t a, std::uint32_t b) const {
  const auto it = edgeUses.find(undirected(a, b));
  if (it == edgeUses.end()) return {};
  return a < b ? it->second : EdgeUse{it->second.backward, it->second.forward};
}

MeshConnectivity buildMeshConnectivity(const Mesh& mesh) {
  MeshConnectivity c;
  const std::size_t nTri = mesh.triangles.size();

  // Weld by exact float equality (std::less on floats: +0 == -0). A
  // non-finite coordinate would break the map's ordering, so such a
  // position stays alone (its triangles are degenerate below).
  std::map<std::array<float, 3>, std::uint32_t> ids;
  c.weldOfPosition.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3 p = mesh.positions[i];
    const auto next = static_cast<std::uint32_t>(c.weldedPositions.size());
    std::uint32_t id = next;
    if (finite(p)) id = ids.emplace(std::array<float, 3>{p.x, p.y, p.z}, next).first->second;
    if (id == next) c.weldedPositions.push_back(p);
    c.weldOfPosition[i] = id;
  }

  // Welded triangles; zero-area ones are left out (exact test in double: a
  // cross product of float differences is exactly zero for collinear
  // float corners of similar magnitude).
  std::vector<std::array<std::uint32_t, 3>> w(nTri);
  std::vector<bool> usable(nTri, false);
  for (std::size_t t = 0; t < nTri; ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh.triangles[t][static_cast<std::size_t>(k)];
      if (i >= mesh.positions.size())
        throw std::invalid_argument("triangle " + std::to_string(t) + " uses position " + std::to_string(i) +
                                    " of " + std::to_string(mesh.positions.size()));
      w[t][static_cast<std::size_t>(k)] = c.weldOfPosition[i];
    }
    const DVec3 a(c.weldedPositions[w[t][0]]), b(c.weldedPositions[w[t][1]]), d(c.weldedPositions[w[t][2]]);
    const DVec3 n = glm::cross(b - a, d - a);
    const bool distinct = w[t][0] != w[t][1] && w[t][1] != w[t][2] && w[t][0] != w[t][2];
    usable[t] = distinct && std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) && glm::dot(n, n) > 0.0;
    if (!usable[t]) c.degenerateTriangles.push_back(static_cast<std::uint32_t>(t));
  }

  // Edge uses, and which triangles use each edge (in triangle order).
  std::map<Key, std::vector<std::uint32_t>> users;
  for (std::size_t t = 0; t < nTri; ++t) {
    if (!usable[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = w[t][static_cast<std::size_t>(k)], b = w[t][static_cast<std::size_t>((k + 1) % 3)];
      EdgeUse& u = c.edgeUses[undirected(a, b)];
      (a < b ? u.forward : u.backward) += 1;
      users[undirected(a, b)].push_back(static_cast<std::uint32_t>(t));
    }
  }
  c.closed = !c.edgeUses.empty();
  std::vector<bool> detached(nTri, false);
  for (const auto& [key, u] : c.edgeUses) {
    if (u.forward != u.backward) c.closed = false;
    if (u.total() == 1) {
      c.boundaryEdges.push_back(u.forward == 1 ? WeldedEdge{key.first, key.second} : WeldedEdge{key.second, key.first});
    } else if (u.total() > 2 || u.forward > 1 || u.backward > 1) {
      c.nonManifoldEdges.push_back({key.first, key.second});
      for (const std::uint32_t t : users[key]) detached[t] = true;
    }
  }

  // Fans: corners at the same welded vertex joined across manifold edges
  // whose two triangles both stay attached.
  Corners corners(3 * nTri);
  auto cornerOf = [&](std::uint32_t t, std::uint32_t v) {
    for (std::uint32_t k = 0; k < 3; ++k)
      if (w[t][k] == v) return 3 * t + k;
    return 3 * t;  // not reached: v is a corner of t
  };
  for (const auto& [key, list] : users) {
    if (list.size() != 2 || detached[list[0]] || detached[list[1]]) continue;
    corners.join(cornerOf(list[0], key.first), cornerOf(list[1], key.first));
    corners.join(cornerOf(list[0], key.second), cornerOf(list[1], key.second));
  }

  // OpenMesh: one vertex per fan, faces in triangle order.
  std::vector<int> vertexOfRoot(3 * nTri, -1);
  std::vector<int> fansOfWeld(c.weldedPositions.size(), 0);
  auto newVertex = [&](std::uint32_t weld) {
    const Vec3 p = c.weldedPositions[weld];
    const auto vh = c.mesh.add_vertex(TriMesh::Point(p.x, p.y, p.z));
    c.weldOfVertex.push_back(weld);
    return vh;
  };
  c.faceOfTriangle.assign(nTri, -1);
  for (std::uint32_t t = 0; t < nTri; ++t) {
    if (!usable[t]) continue;
    std::array<OpenMesh::VertexHandle, 3> vh;
    if (!detached[t]) {
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t root = corners.find(3 * t + k);
        if (vertexOfRoot[root] < 0) {
          vertexOfRoot[root] = newVertex(w[t][k]).idx();
          fansOfWeld[w[t][k]] += 1;
        }
        vh[k] = OpenMesh::VertexHandle(vertexOfRoot[root]);
      }
    }
    OpenMesh::FaceHandle fh;
    if (!detached[t]) fh = c.mesh.add_face(vh[0], vh[1], vh[2]);
    // Manifold fans always connect; should OpenMesh still refuse one, the
    // triangle goes in detached rather than being lost.
    if (!fh.is_valid()) {
      if (!detached[t]) detached[t] = true;
      for (std::uint32_t k = 0; k < 3; ++k) vh[k] = newVertex(w[t][k]);
      fh = c.mesh.add_face(vh[0], vh[1], vh[2]);
    }
    if (detached[t]) c.detachedTriangles.push_back(t);
    c.faceOfTriangle[t] = fh.idx();
    c.triangleOfFace.push_back(t);
  }
  for (const int n : fansOfWeld) c.splitVertices += n > 1 ? 1 : 0;
  return c;
}

}  // namespace mpr
