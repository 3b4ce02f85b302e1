#pragma once
// Shared by the OFF and PLY reader tests: a file in the test's temporary
// folder, and OpenMesh's own reading of it to hold MPR's against.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace mpr {

inline std::string writeFile(const std::string& name, const std::string& bytes) {
  const std::string path = (std::filesystem::path(::testing::TempDir()) / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// What mesh_loader made of a mesh before MPR read OFF and PLY itself:
// OpenMesh's reader, then the same normals and faces.
inline Mesh loadWithOpenMesh(const std::string& path) {
  OpenMesh::PolyMesh_ArrayKernelT<> pm;
  pm.request_face_normals();
  pm.request_vertex_normals();
  OpenMesh::IO::Options opt;
  EXPECT_TRUE(OpenMesh::IO::read_mesh(pm, path, opt));
  pm.update_normals();
  Mesh m;
  for (const auto vh : pm.vertices()) {
    m.positions.emplace_back(pm.point(vh)[0], pm.point(vh)[1], pm.point(vh)[2]);
    m.normals.emplace_back(pm.normal(vh)[0], pm.normal(vh)[1], pm.normal(vh)[2]);
  }
  for (const auto fh : pm.faces()) {
    std::vector<std::uint32_t> face;
    for (const auto vh : pm.fv_range(fh)) face.push_back(static_cast<std::uint32_t>(vh.idx()));
    m.faces.push_back(face);
  }
  return m;
}

// Positions and normals bit for bit, faces as lists.
inline void expectSameMesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  ASSERT_EQ(a.faces, b.faces);
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_EQ(std::memcmp(&a.positions[i], &b.positions[i], sizeof a.positions[i]), 0) << "vertex " << i;
    EXPECT_EQ(std::memcmp(&a.normals[i], &b.normals[i], sizeof a.normals[i]), 0) << "normal " << i;
  }
}

}  // namespace mpr
