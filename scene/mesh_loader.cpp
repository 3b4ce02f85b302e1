#include "scene/mesh_loader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "util/input_file.hpp"

namespace mpr {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Mesh readMesh(const std::string& path);

namespace {

// A plain ASCII OFF body, line by line, before OpenMesh reads it: a face
// line whose vertex count is garbage made OpenMesh grow a vector to 2 GB
// (found by fuzz/mesh_fuzzer). Every vertex line holds three numbers and every
// face line a count 1..vertices and that many indices below `vertices`.
void checkOffBody(const std::string& path, std::uint64_t vertices, std::uint64_t faces) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  auto refuse = [&](std::uint64_t lineNo, const std::string& why) {
    throw std::runtime_error("mesh file '" + path + "' line " + std::to_string(lineNo) + ": " + why);
  };
  std::uint64_t lineNo = 0, counts = 0, v = 0, f = 0;
  auto isNumber = [](const std::string& t) {
    char* end = nullptr;
    std::strtod(t.c_str(), &end);
    return !t.empty() && end == t.c_str() + t.size();
  };
  while (f < faces && std::getline(in, line)) {
    ++lineNo;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream w(line);
    std::vector<std::string> tokens;
    for (std::string t; w >> t;) tokens.push_back(t);
    if (lineNo == 1) continue;  // the OFF line: OpenMesh reads nothing more from it
    if (tokens.empty()) continue;
    if (counts < 3) {  // the counts, from the line after OFF on
      counts += tokens.size();
      continue;
    }
    if (v < vertices) {
      if (tokens.size() < 3 || !isNumber(tokens[0]) || !isNumber(tokens[1]) || !isNumber(tokens[2]))
        refuse(lineNo, "a vertex needs three numbers");
      ++v;
      continue;
    }
    char* end = nullptr;
    const unsigned long long k = std::strtoull(tokens[0].c_str(), &end, 10);
    if (end != tokens[0].c_str() + tokens[0].size() || tokens[0][0] == '-' || k < 1 || k > vertices ||
        tokens.size() < k + 1)
      refuse(lineNo, "a face needs a vertex count from 1 to " + std::to_string(vertices) + " and that many indices");
    for (std::size_t i = 1; i <= k; ++i) {
      const unsigned long long idx = std::strtoull(tokens[i].c_str(), &end, 10);
      if (end != tokens[i].c_str() + tokens[i].size() || tokens[i][0] == '-' || idx >= vertices)
        refuse(lineNo, "a face's vertex index must be below " + std::to_string(vertices));
    }
    ++f;
  }
  if (v < vertices || f < faces) refuse(lineNo, "the file ends before its " + std::to_string(vertices) +
                                                   " vertices and " + std::to_string(faces) + " faces");
}

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

// The element counts an OFF or PLY header claims, checked against the file's
// size before OpenMesh reserves memory for them: every vertex takes at least
// three bytes (three coordinates) and every face one, in ASCII or binary, so
// a 40-byte file cannot claim 2e9 vertices and allocate gigabytes.
void checkHeaderCounts(const std::string& path, std::uint64_t size) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") checkObjFaces(path);
  if (ext != ".off" && ext != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::string head(std::min<std::uint64_t>(size, 1 << 20), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::istringstream h(head);
  std::uint64_t vertices = 0, faces = 0;
  auto refuse = [&](const std::string& why) { throw std::runtime_error("mesh file '" + path + "' " + why); };
  if (ext == ".off") {
    std::string word;
    while (h >> word && word[0] == '#') std::getline(h, word);  // comments
    if (word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0) refuse("does not start with OFF");
    // OpenMesh skips the rest of the OFF line and reads the counts from the
    // lines after it: counts on the OFF line itself would be passed over and
    // the first vertex read as counts ("OFF 0 0 1" then "-3 0" claimed 2^32
    // vertices; found by fuzz/mesh_fuzzer). BINARY OFF has its counts in
    // binary (left to OpenMesh, after the size check); a dimension follows nOFF.
    std::string magicRest, next;
    std::getline(h, magicRest);
    std::istringstream rest(magicRest);
    if (rest >> next) {
      if (next == "BINARY") return;
      refuse("has '" + next + "' on its OFF line: the counts go on the line after it");
    }
    if (!(h >> next)) refuse("has no vertex and face counts after OFF");
    if (word[0] == 'n') h >> next;
    // Counts are plain decimal digits: "0u20(" is not 0 (OpenMesh read it
    // otherwise and ran out of memory; found by fuzz/mesh_fuzzer).
    auto count = [&](const std::string& t, const char* what) {
      if (t.empty() || t.size() > 18 || t.find_first_not_of("0123456789") != std::string::npos)
        refuse(std::string("has no ") + what + " count after OFF (a plain number)");
      return std::stoull(t);
    };
    std::string faceText, edgeText;
    vertices = count(next, "vertex");
    if (!(h >> faceText)) refuse("has no face count after OFF");
    faces = count(faceText, "face");
    if (!(h >> edgeText)) refuse("has no edge count after OFF");
    (void)count(edgeText, "edge");
  } else {
    // OpenMesh's PLY reader loops forever on a header that never ends (found
    // by fuzz/mesh_fuzzer): the header must start with "ply" and close with
    // end_header within the first MiB.
    std::string line;
    if (!std::getline(h, line) || line.rfind("ply", 0) != 0) refuse("does not start with ply");
    // OpenMesh also loops on header lines it does not know, so every line is
    // checked against the PLY grammar before OpenMesh sees the file.
    static const char* const kTypes[] = {"char",  "uchar",  "short", "ushort", "int",   "uint",   "float",
                                         "double", "int8",  "uint8", "int16",  "uint16", "int32", "uint32",
                                         "float32", "float64"};
    auto isType = [](const std::string& t) {
      return std::any_of(std::begin(kTypes), std::end(kTypes), [&](const char* k) { return t == k; });
    };
    bool ended = false, sawFormat = false, sawElement = false;
    while (std::getline(h, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line == "end_header") {  // exactly: "end_header\0..." made OpenMesh loop too
        ended = true;
        break;
      }
      std::istringstream w(line);
      std::string word, a, b, c, extra;
      w >> word;
      if (word == "comment" || word == "obj_info") continue;
      if (word == "format") {
        if (!(w >> a >> b) || (a != "ascii" && a != "binary_little_endian" && a != "binary_big_endian") || b != "1.0" ||
            (w >> extra))
          refuse("has a bad format line: '" + line + "'");
        sawFormat = true;
        continue;
      }
      if (word == "property") {
        if (!sawElement) refuse("has a property before any element: '" + line + "'");
        const bool ok = (w >> a) && (a == "list" ? (w >> b >> c) && isType(b) && isType(c) && (w >> extra) : isType(a) && (w >> b));
        std::string more;
        if (!ok || (w >> more)) refuse("has a bad property line: '" + line + "'");
        continue;
      }
      if (word != "element") refuse("has a header line PLY does not know: '" + line + "'");
      sawElement = true;
      std::string name;
      long long n = -1;
      if (!(w >> name >> n) || n < 0 || (w >> extra)) refuse("has an element line without a count: '" + line + "'");
      if (name == "vertex") vertices = static_cast<std::uint64_t>(n);
      else if (name == "face") faces = static_cast<std::uint64_t>(n);
    }
    if (!ended) refuse("has no end_header line closing its header");
    if (!sawFormat) refuse("has no format line");
  }
  if (vertices > size / 3 || faces > size || vertices * 3 + faces > size)
    refuse("claims " + std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces, more than its " +
           std::to_string(size) + " bytes can hold");
  if (ext == ".off" && head.rfind("OFF", 0) == 0) checkOffBody(path, vertices, faces);
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
