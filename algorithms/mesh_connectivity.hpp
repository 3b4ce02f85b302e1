#pragma once
// Half-edge connectivity of a scene mesh, for silhouette extraction (shadow
// volumes, 1994 paper: "silhouette faces ... for each edge of an object").
// Scene meshes repeat positions along hard edges (a box has 24 positions
// for 8 corners), so the triangles are first welded by EXACT position
// equality (no tolerance: only bit-equal coordinates are one vertex; +0 and
// -0 are equal) and then built into an OpenMesh TriMesh.
//
// OpenMesh cannot represent non-manifold configurations; they are made
// representable without dropping any triangle:
//  - a triangle with a non-manifold edge (an edge used by more than two
//    triangles, or twice in the same direction: inconsistent winding) is
//    added "detached", with its own three OpenMesh vertices;
//  - a welded vertex whose triangles form several separate fans (two cones
//    touching at their tips) gets one OpenMesh vertex per fan.
// Zero-area triangles (two corners welded together, or collinear corners,
// decided exactly in double) are left out: they have no plane, so they are
// neither lit nor unlit, and they hide nothing.
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "scene/scene.hpp"

namespace mpr {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// A welded edge: weld ids (indices into MeshConnectivity::weldedPositions).
struct WeldedEdge {
  std::uint32_t a = 0, b = 0;
  bool operator==(const WeldedEdge&) const = default;
};

// How often the triangles use an undirected welded edge {lo, hi} (lo < hi)
// in each direction.
struct EdgeUse {
  int forward = 0;   // lo -> hi
  int backward = 0;  // hi -> lo
  int total() const { return forward + backward; }
};

struct MeshConnectivity {
  TriMesh mesh;                                // every non-degenerate triangle, one face each
  std::vector<Vec3> weldedPositions;           // weld id -> position (first occurrence's bits)
  std::vector<std::uint32_t> weldOfPosition;   // Mesh::positions index -> weld id
  std::vector<std::uint32_t> weldOfVertex;     // TriMesh vertex index -> weld id
  std::vector<std::uint32_t> triangleOfFace;   // TriMesh face index -> Mesh::triangles index
  std::vector<int> faceOfTriangle;             // Mesh::triangles index -> TriMesh face index, -1: degenerate
  std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> edgeUses;  // key (lo, hi), lo < hi

  std::vector<std::uint32_t> degenerateTriangles;  // zero area, left out
  std::vector<WeldedEdge> boundaryEdges;           // used by one triangle, directed as in it
  std::vector<WeldedEdge> nonManifoldEdges;        // (lo, hi): > 2 uses, or 2 in one direction
  std::vector<std::uint32_t> detachedTriangles;    // on a non-manifold edge (own TriMesh vertices)
  std::size_t splitVertices = 0;                   // welded vertices with several fans
  // Every welded edge is used as often in one direction as in the other:
  // the triangles bound a solid. For a manifold mesh this is exactly "no
  // boundary edges (and consistent winding)"; it also holds for closed
  // non-manifold meshes (two boxes sharing an edge), whose shadow volumes
  // are still exact (see silhouette.hpp).
  bool closed = false;

  std::size_t edgeCount() const { return edgeUses.size(); }      // welded undirected edges
  std::size_t triangleCount() const { return triangleOfFace.size(); }
  bool manifold() const { return nonManifoldEdges.empty() && splitVertices == 0; }
  // The use counts of the welded edge {a, b} (zero counts if unused).
  EdgeUse uses(std::uint32_t a, std::uint32_t b) const;
};

// Welds and connects `mesh`. Throws std::invalid_argument for a triangle
// index past the positions.
MeshConnectivity buildMeshConnectivity(const Mesh& mesh);

}  // namespace mpr
