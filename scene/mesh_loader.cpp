#include "scene/mesh_loader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace mpr {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Mesh loadMeshFile(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("mesh file '" + path + "' does not exist");
  if (!std::ifstream(path)) throw std::runtime_error("mesh file '" + path + "' cannot be read");
  PolyMesh pm;
  pm.request_face_normals();
  pm.request_vertex_normals();
  OpenMesh::IO::Options opt;
  if (!OpenMesh::IO::read_mesh(pm, path, opt))
    throw std::runtime_error("OpenMesh cannot read '" + path + "' (supported: .obj .off .ply .stl)");
  if (pm.n_faces() == 0) throw std::runtime_error("mesh file '" + path + "' has no faces");
  pm.update_normals();
  Mesh m;
  for (const auto vh : pm.vertices()) {
    const auto& p = pm.point(vh);
    const auto& n = pm.normal(vh);
    m.positions.emplace_back(p[0], p[1], p[2]);
    m.normals.emplace_back(n[0], n[1], n[2]);
  }
  for (const auto fh : pm.faces()) {
    std::vector<std::uint32_t> face;
    for (const auto vh : pm.fv_range(fh)) face.push_back(static_cast<std::uint32_t>(vh.idx()));
    for (std::size_t i = 1; i + 1 < face.size(); ++i) m.triangles.push_back({face[0], face[i], face[i + 1]});
    m.faces.push_back(std::move(face));
  }
  return m;
}

}  // namespace mpr
