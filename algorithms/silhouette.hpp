#pragma once
// The silhouette of a mesh as seen from a point light, from the OpenMesh
// half-edge connectivity (mesh_connectivity.hpp): the edges whose silhouette
// faces bound the shadow volume (1994 paper: "Shadow volumes are volumes
// bounded by silhouette faces ... created for each edge of an object by
// extending that edge away from the light source"; Heidmann's in-out
// counting then needs only the edges between lit and unlit faces).
//
// Lit: the light strictly on the front side of the triangle's plane (the
// side its counter-clockwise winding faces), decided in double. A light in
// the plane leaves the triangle unlit; zero-area triangles are neither lit
// nor unlit (MeshConnectivity::degenerateTriangles).
//
// Silhouette edges are the boundary of the lit set: an edge between a lit
// and an unlit triangle, or a boundary edge of a lit triangle. Counted per
// welded edge with signs (a lit triangle using it one way +1, the other way
// -1), so an edge where two lit triangles meet cancels even across
// non-manifold junctions, and closed non-manifold meshes still give closed
// volumes.
//
// Open meshes: a boundary edge of a lit triangle is a silhouette edge, so
// the volume (shadow_volume.hpp) is still a closed surface and counts
// consistently, but it is the shadow of the lit triangles only: an open
// mesh seen from its back side (e.g. the inside of a box without a lid)
// casts less shadow than the solid would. `closed` is false then and the
// caller should warn.
#include <cstdint>
#include <vector>

#include "algorithms/mesh_connectivity.hpp"

namespace mpr {

// One silhouette edge, directed so that its silhouette face
// a, b, extrude(b), extrude(a) is counter-clockwise seen from outside the
// shadow volume (a -> b runs against the lit triangle's winding).
struct SilhouetteEdge {
  std::uint32_t a = 0, b = 0;  // weld ids
  Vec3 pa{0.0f}, pb{0.0f};     // their positions (bit-identical to the mesh's)
  bool boundary = false;       // a boundary edge of the mesh (open there)
};

struct Silhouette {
  std::vector<SilhouetteEdge> edges;         // in the TriMesh's edge order
  std::vector<std::uint32_t> litTriangles;   // Mesh::triangles indices: the light cap
  std::vector<std::uint32_t> unlitTriangles; // Mesh::triangles indices (degenerate ones in neither)
  std::size_t boundaryEdgeCount = 0;         // boundary edges of the mesh (lit or not)
  std::size_t boundarySilhouetteEdges = 0;   // silhouette edges that are boundary edges
  bool closed = false;                       // MeshConnectivity::closed
};

// True when `light` lies strictly on the front side of the plane of the
// counter-clockwise triangle a, b, c (double precision; false for a
// zero-area triangle and for a light in its plane).
bool triangleFacesLight(Vec3 a, Vec3 b, Vec3 c, Vec3 light);

// The silhouette of `mesh` (connected by `connectivity`, built from the same
// mesh) seen from a point light at `light`.
Silhouette findSilhouette(const Mesh& mesh, const MeshConnectivity& connectivity, Vec3 light);

}  // namespace mpr
