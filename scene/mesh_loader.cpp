#include "scene/mesh_loader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "scene/off_reader.hpp"
#include "scene/ply_reader.hpp"
#include "util/input_file.hpp"

namespace mpr {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Mesh readMesh(const std::string& path);

namespace {

// OBJ face lines, before OpenMesh reads them: a face corner without a vertex
// index ("f /2 3 4") trips an assertion in Debian's OpenMesh and aborts
// (found by fuzz/mesh_fuzzer). Every corner of an f line needs a vertex
// index naming a vertex before it (1-based, or negative from the last).
void checkObjFaces(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uint64_t lineNo = 0;
  long long vertices = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream w(line);
    std::string kind;
    if (!(w >> kind)) continue;
    if (kind == "v") ++vertices;
    if (kind != "f") continue;
    int corners = 0;
    for (std::string t; w >> t; ++corners) {
      const std::string index = t.substr(0, t.find('/'));
      char* end = nullptr;
      const long long i = std::strtoll(index.c_str(), &end, 10);
      if (index.empty() || end != index.c_str() + index.size() || i == 0 || i > vertices || -i > vertices)
        throw std::runtime_error("mesh file '" + path + "' line " + std::to_string(lineNo) + ": face corner '" + t +
                                 "' does not name one of the " + std::to_string(vertices) + " vertices before it");
    }
    if (corners < 3)
      throw std::runtime_error("mesh file '" + path + "' line " + std::to_string(lineNo) + ": a face needs three corners");
  }
}

// An OFF or PLY file read by MPR (off_reader.hpp, ply_reader.hpp say why),
// its vertices and faces handed to OpenMesh's importer in the order and with
// the reservation OpenMesh's own readers use.
void importPolygons(const std::string& path, const std::string& ext, PolyMesh& pm) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("mesh file '" + path + "' cannot be read");
  const PolygonFile file = ext == ".off" ? parseOff(bytes, path) : parsePly(bytes, path);
  OpenMesh::IO::ImporterT<PolyMesh> importer(pm);
  const auto vertices = static_cast<unsigned>(file.points.size());
  importer.reserve(vertices, 3 * vertices, static_cast<unsigned>(file.faces.size()));
  for (const auto& p : file.points) importer.add_vertex(OpenMesh::Vec3f(p[0], p[1], p[2]));
  OpenMesh::IO::BaseImporter::VHandles handles;
  for (const auto& face : file.faces) {
    handles.clear();
    for (const std::uint32_t i : face) handles.push_back(OpenMesh::VertexHandle(static_cast<int>(i)));
    importer.add_face(handles);
  }
}

}  // namespace

Mesh loadMeshFile(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("mesh file '" + path + "' does not exist");
  if (const std::string why = inputFileProblem(path, kMaxMeshBytes, "mesh file '" + path + "'"); !why.empty())
    throw std::runtime_error(why);
  try {
    return readMesh(path);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("mesh file '" + path + "' needs more memory than this process may use");
  }
}

Mesh readMesh(const std::string& path) {
  PolyMesh pm;
  pm.request_face_normals();
  pm.request_vertex_normals();
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  OpenMesh::IO::Options opt;
  if (ext == ".obj") checkObjFaces(path);
  if (ext == ".off" || ext == ".ply")
    importPolygons(path, ext, pm);
  else if (!OpenMesh::IO::read_mesh(pm, path, opt))
    throw std::runtime_error("OpenMesh cannot read '" + path + "' (supported: .obj .off .ply .stl)");
  if (pm.n_faces() == 0) throw std::runtime_error("mesh file '" + path + "' has no faces");
  pm.update_normals();
  Mesh m;
  for (const auto vh : pm.vertices()) {
    const auto& p = pm.point(vh);
    const auto& n = pm.normal(vh);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::runtime_error("mesh file '" + path + "' has a vertex that is not finite (vertex " +
                               std::to_string(vh.idx()) + ")");
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
