#include "scene/mesh_loader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <stdexcept>

#include "util/input_file.hpp"

namespace mpr {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Mesh readMesh(const std::string& path);

namespace {

// The element counts an OFF or PLY header claims, checked against the file's
// size before OpenMesh reserves memory for them: every vertex takes at least
// three bytes (three coordinates) and every face one, in ASCII or binary, so
// a 40-byte file cannot claim 2e9 vertices and allocate gigabytes.
void checkHeaderCounts(const std::string& path, std::uint64_t size) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".off" && ext != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::istringstream h(head);
  std::uint64_t vertices = 0, faces = 0;
  auto refuse = [&](const std::string& why) { throw std::runtime_error("mesh file '" + path + "' " + why); };
  if (ext == ".off") {
    std::string word;
    while (h >> word && word[0] == '#') std::getline(h, word);  // comments
    if (word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0) refuse("does not start with OFF");
    // A dimension follows nOFF; BINARY OFF has its counts in binary (left to OpenMesh, after the size check).
    std::string next;
    if (!(h >> next)) refuse("has no vertex and face counts after OFF");
    if (next == "BINARY") return;
    if (word[0] == 'n') h >> next;
    long long v = -1, f = -1;
    try {
      v = std::stoll(next);
    } catch (const std::exception&) {
      refuse("has no vertex count after OFF");
    }
    if (!(h >> f)) refuse("has no face count after OFF");
    if (v < 0 || f < 0) refuse("has negative counts");
    vertices = static_cast<std::uint64_t>(v), faces = static_cast<std::uint64_t>(f);
  } else {
    std::string line;
    while (std::getline(h, line) && line.rfind("end_header", 0) != 0) {
      std::istringstream l(line);
      std::string kw, name;
      long long n = -1;
      if (!(l >> kw) || kw != "element") continue;
      if (!(l >> name >> n) || n < 0) refuse("has an element line without a count: '" + line + "'");
      if (name == "vertex") vertices = static_cast<std::uint64_t>(n);
      else if (name == "face") faces = static_cast<std::uint64_t>(n);
    }
  }
  if (vertices > size / 3 || faces > size || vertices * 3 + faces > size)
    refuse("claims " + std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces, more than its " +
           std::to_string(size) + " bytes can hold");
}

}  // namespace

Mesh loadMeshFile(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("mesh file '" + path + "' does not exist");
  if (const std::string why = inputFileProblem(path, kMaxMeshBytes, "mesh file '" + path + "'"); !why.empty())
    throw std::runtime_error(why);
  checkHeaderCounts(path, std::filesystem::file_size(path));
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
  OpenMesh::IO::Options opt;
  if (!OpenMesh::IO::read_mesh(pm, path, opt))
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
