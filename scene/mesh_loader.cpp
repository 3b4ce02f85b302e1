#include "scene/mesh_loader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <new>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "scene/off_reader.hpp"
#include "scene/ply_reader.hpp"
#include "util/input_file.hpp"

namespace mpr {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Mesh readMesh(const std::string& path, std::vector<std::string>& warnings);

namespace {

// OpenMesh reports what it does to a mesh on its own streams (omerr, omlog,
// omout), which write to standard error and output: raw lines such as
// "ImporterT: Face has equal vertices" reached the user beside MPR's
// messages, and with them a face dropped without MPR saying so. While a
// mesh is read the standard streams those write to are pointed at a string
// (one reader at a time), which readMesh turns into MPR's warnings.
// OpenMesh's own targets are left alone: its disconnect() drops a target
// without freeing it, six leaked objects per mesh (LeakSanitizer).
class OpenMeshMessages {
 public:
  OpenMeshMessages() : lock_(mutex()) {
    flushOpenMesh();
    for (std::ostream* s : {&std::cerr, &std::cout, &std::clog}) kept_.push_back({s, s->rdbuf(text_.rdbuf())});
  }
  ~OpenMeshMessages() {
    flushOpenMesh();
    for (const Kept& k : kept_) k.stream->rdbuf(k.buffer);
  }
  OpenMeshMessages(const OpenMeshMessages&) = delete;
  OpenMeshMessages& operator=(const OpenMeshMessages&) = delete;

  // The lines written so far.
  std::vector<std::string> lines() {
    flushOpenMesh();
    std::vector<std::string> out;
    std::istringstream in(text_.str());
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) out.push_back(line);
    return out;
  }

 private:
  struct Kept {
    std::ostream* stream;
    std::streambuf* buffer;
  };
  static void flushOpenMesh() {
    for (OpenMesh::mostream* s : streams()) s->flush();
  }
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::vector<OpenMesh::mostream*> streams() { return {&omerr(), &omlog(), &omout()}; }
  std::lock_guard<std::mutex> lock_;
  std::ostringstream text_;
  std::vector<Kept> kept_;
};

// OBJ face lines, before OpenMesh reads them: a face corner without a vertex
// index ("f /2 3 4") trips an assertion in Debian's OpenMesh and aborts
// (found by fuzz/mesh_fuzzer). Every corner of an f line needs a vertex
// index naming a vertex before it (1-based, or negative from the last).
// Returns how many faces the file gives.
std::uint64_t checkObjFaces(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uint64_t lineNo = 0;
  long long vertices = 0;
  std::uint64_t faces = 0;
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
    ++faces;
  }
  return faces;
}

// How many facets an STL file gives, decided as OpenMesh's STL reader
// decides (binary when the size is 84 + 50 n for the n in bytes 80..83;
// ASCII facets each an "outer loop" line).
std::uint64_t stlFacets(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
    const std::uint64_t n = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint64_t{b[3]} << 24);
    if (bytes.size() == 84 + 50 * n) return n;
  }
  std::uint64_t facets = 0;
  std::istringstream lines(bytes);
  for (std::string line; std::getline(lines, line);)
    if (line.find("outer") != std::string::npos || line.find("OUTER") != std::string::npos) ++facets;
  return facets;
}

// An OFF or PLY file read by MPR (off_reader.hpp, ply_reader.hpp say why),
// its vertices and faces handed to OpenMesh's importer in the order and with
// the reservation OpenMesh's own readers use.
// Returns how many faces the file gives.
std::uint64_t importPolygons(const std::string& path, const std::string& ext, PolyMesh& pm) {
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
  return file.faces.size();
}

// OpenMesh's messages and the faces it dropped as MPR's warnings. Its
// readers drop a degenerate face (fewer than three corners, a corner
// repeated; OBJ and STL without a word, ImporterT with a line on omerr), so
// they are counted: the faces the file gives less those the mesh has. Faces
// it kept only by giving them vertices of their own (non-manifold ones) in
// a second line; any other message once, quoted.
std::vector<std::string> meshWarnings(const std::vector<std::string>& lines, std::uint64_t fileFaces,
                                      std::uint64_t meshFaces) {
  std::uint64_t complex = 0, others = 0;
  std::string other;
  for (const std::string& l : lines) {
    if (l.find("Face has equal vertices") != std::string::npos ||
        l.find("Face contains invalid vertex index") != std::string::npos)
      continue;  // counted below
    if (l.find("complex vertex") != std::string::npos || l.find("complex edge") != std::string::npos ||
        l.find("patch re-linking failed") != std::string::npos)
      ++complex;
    else if (others++ == 0)
      other = l.substr(0, 200);
  }
  std::vector<std::string> w;
  if (fileFaces > meshFaces) {
    const std::uint64_t dropped = fileFaces - meshFaces;
    w.push_back(std::to_string(dropped) + " of its " + std::to_string(fileFaces) + " faces dropped as degenerate " +
                "(fewer than three corners, or a corner repeated)");
  }
  if (complex > 0)
    w.push_back(std::to_string(complex) + " non-manifold face" + (complex == 1 ? "" : "s") + " kept with vertices of " +
                (complex == 1 ? "its" : "their") + " own (not smoothed with " + (complex == 1 ? "its" : "their") +
                " neighbours)");
  if (others > 0)
    w.push_back("OpenMesh said: " + other + (others > 1 ? " (and " + std::to_string(others - 1) + " more lines)" : ""));
  return w;
}

}  // namespace

Mesh loadMeshFile(const std::string& path, std::vector<std::string>* warnings) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("mesh file '" + path + "' does not exist");
  if (const std::string why = inputFileProblem(path, kMaxMeshBytes, "mesh file '" + path + "'"); !why.empty())
    throw std::runtime_error(why);
  try {
    std::vector<std::string> w;
    Mesh m = readMesh(path, w);
    if (warnings) warnings->insert(warnings->end(), w.begin(), w.end());
    return m;
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("mesh file '" + path + "' needs more memory than this process may use");
  }
}

Mesh readMesh(const std::string& path, std::vector<std::string>& warnings) {
  PolyMesh pm;
  pm.request_face_normals();
  pm.request_vertex_normals();
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  OpenMesh::IO::Options opt;
  std::uint64_t fileFaces = 0;
  if (ext == ".obj") fileFaces = checkObjFaces(path);
  if (ext == ".stl") fileFaces = stlFacets(path);
  {
    OpenMeshMessages messages;
    if (ext == ".off" || ext == ".ply") {
      fileFaces = importPolygons(path, ext, pm);
    } else if (!OpenMesh::IO::read_mesh(pm, path, opt)) {
      const std::vector<std::string> said = messages.lines();
      throw std::runtime_error("OpenMesh cannot read '" + path + "' (supported: .obj .off .ply .stl)" +
                               (said.empty() ? "" : "; it said: " + said.front().substr(0, 200)));
    }
    warnings = meshWarnings(messages.lines(), fileFaces, pm.n_faces());
  }
  if (pm.n_faces() == 0)
    throw std::runtime_error("mesh file '" + path + "' has no faces" +
                             (warnings.empty() ? "" : " that OpenMesh kept: " + warnings.front()));
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
