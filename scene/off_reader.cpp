// OFF files read line by line (see off_reader.hpp).
#include "scene/off_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/mesh_tokens.hpp"

namespace mpr {
namespace {

// The file's lines one at a time, split into tokens, '#' comments dropped.
class OffLines {
 public:
  explicit OffLines(std::string_view bytes) : bytes_(bytes) {}

  // The next line that has tokens; false at the end of the file.
  bool next(std::vector<MeshWord>& tokens) {
    while (pos_ < bytes_.size()) {
      const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
      std::string_view line = bytes_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      splitMeshWords(line, tokens);
      if (!tokens.empty()) return true;
    }
    return false;
  }

  std::uint64_t line() const { return line_; }
  // The first byte after the current line.
  std::size_t offset() const { return std::min(pos_, bytes_.size()); }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::uint64_t line_ = 0;
};

// "[ST][C][N]OFF": what OpenMesh's can_u_read accepts, less the 4 and n
// (other dimensions) it refuses too.
bool isOffMagic(std::string_view t) {
  if (t.substr(0, 2) == "ST") t.remove_prefix(2);
  if (t.substr(0, 1) == "C") t.remove_prefix(1);
  if (t.substr(0, 1) == "N") t.remove_prefix(1);
  return t == "OFF";
}

// OpenMesh's read_binary: little-endian uint32 counts (vertices, faces,
// edges), three float32 per vertex, then per face a uint32 size and as many
// uint32 indices; no colours after plain OFF.
PolygonFile parseBinaryOff(std::string_view bytes, std::size_t start, const std::string& name) {
  std::size_t at = start;
  auto refuseAt = [&](std::size_t byte, const std::string& why) { refuseMeshByte(name, byte, why); };
  auto u32 = [&](const char* what) {
    if (bytes.size() - at < 4) refuseAt(at, std::string("the file ends inside ") + what);
    std::uint32_t v = 0;
    for (int b = 3; b >= 0; --b) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(b)]);
    at += 4;
    return v;
  };
  const std::uint64_t vertices = u32("the vertex count"), faces = u32("the face count");
  (void)u32("the edge count");
  const std::uint64_t left = bytes.size() - at;
  if (vertices * 12 > left || faces * 4 > left || vertices * 12 + faces * 4 > left)
    refuseAt(start, meshCountsTooLarge(vertices, faces, bytes.size()));
  PolygonFile m;
  m.points.reserve(vertices);
  m.faces.reserve(faces);
  for (std::uint64_t v = 0; v < vertices; ++v) {
    std::array<float, 3> p{};
    for (float& c : p) {
      const std::size_t byte = at;
      const std::uint32_t raw = u32("a vertex");
      std::memcpy(&c, &raw, sizeof c);
      if (!std::isfinite(c)) refuseAt(byte, "vertex " + std::to_string(v) + " has a coordinate that is not finite");
    }
    m.points.push_back(p);
  }
  for (std::uint64_t f = 0; f < faces; ++f) {
    const std::size_t byte = at;
    const std::uint64_t k = u32("a face's size");
    if (k < 1 || k > vertices || k * 4 > bytes.size() - at)
      refuseAt(byte, "face " + std::to_string(f) + " claims " + std::to_string(k) +
                         " vertices; a face has 1 to " + std::to_string(vertices) + " and the file must hold them");
    std::vector<std::uint32_t> face(k);
    for (std::uint32_t& idx : face) {
      const std::size_t indexByte = at;
      idx = u32("a face");
      if (idx >= vertices)
        refuseAt(indexByte, "face " + std::to_string(f) + " names vertex " + std::to_string(idx) + " of " +
                                std::to_string(vertices));
    }
    m.faces.push_back(std::move(face));
  }
  return m;
}

}  // namespace

PolygonFile parseOff(std::string_view bytes, const std::string& name) {
  OffLines lines(bytes);
  std::vector<MeshWord> tokens;
  if (!lines.next(tokens)) refuseMeshLine(name, std::max<std::uint64_t>(lines.line(), 1), 1, "is empty: an OFF file starts with OFF");
  if (!isOffMagic(tokens[0].text)) {
    const bool otherDimension = tokens[0].text.find("4OFF") != std::string_view::npos ||
                                tokens[0].text.find("nOFF") != std::string_view::npos;
    refuseMeshLine(name, lines.line(), tokens[0].column,
           otherDimension ? "4OFF and nOFF (vertices of other than three coordinates) are not supported"
                          : "does not start with OFF (or STOFF, COFF, NOFF)");
  }
  if (tokens.size() > 1 && tokens[1].text == "BINARY") {
    if (tokens[0].text != "OFF" || tokens.size() > 2)
      refuseMeshLine(name, lines.line(), tokens[1].column, "only a plain 'OFF BINARY' line is read in binary");
    return parseBinaryOff(bytes, lines.offset(), name);
  }

  // The three counts: on the OFF line after the keyword, or on the lines after it.
  std::uint64_t counts[3] = {0, 0, 0};
  static const char* const kCountNames[3] = {"vertex", "face", "edge"};
  int have = 0;
  std::size_t first = 1;
  while (have < 3) {
    if (first >= tokens.size()) {
      if (!lines.next(tokens))
        refuseMeshLine(name, lines.line(), 1,
               have == 0 ? "has no vertex and face counts after OFF"
                         : std::string("has no ") + kCountNames[have] + " count after OFF");
      first = 0;
    }
    for (std::size_t i = first; i < tokens.size(); ++i) {
      if (have == 3)
        refuseMeshLine(name, lines.line(), tokens[i].column, quotedMeshToken(tokens[i].text) + " follows the three counts on their line");
      if (!parseMeshUnsigned(tokens[i].text, counts[have]))
        refuseMeshLine(name, lines.line(), tokens[i].column,
               std::string("the ") + kCountNames[have] + " count " + quotedMeshToken(tokens[i].text) +
                   " is not a plain number below 2^32");
      ++have;
    }
    first = tokens.size();
  }
  const std::uint64_t vertices = counts[0], faces = counts[1];
  // Every vertex takes at least three bytes and every face one, so a 40-byte
  // file cannot have 2e9 vertices reserved for it.
  if (vertices > bytes.size() / 3 || faces > bytes.size() || vertices * 3 + faces > bytes.size())
    refuseMeshLine(name, lines.line(), tokens[0].column, meshCountsTooLarge(vertices, faces, bytes.size()));

  PolygonFile m;
  m.points.reserve(vertices);
  m.faces.reserve(faces);
  while (m.points.size() < vertices) {
    if (!lines.next(tokens))
      refuseMeshLine(name, lines.line(), 1, "the file ends after " + std::to_string(m.points.size()) + " of its " +
                                        std::to_string(vertices) + " vertices");
    if (tokens.size() < 3) refuseMeshLine(name, lines.line(), tokens[0].column, "a vertex needs three numbers (x y z)");
    std::array<float, 3> p{};
    for (int c = 0; c < 3; ++c)
      if (!parseMeshFloat(tokens[static_cast<std::size_t>(c)].text, p[static_cast<std::size_t>(c)]))
        refuseMeshLine(name, lines.line(), tokens[static_cast<std::size_t>(c)].column,
               quotedMeshToken(tokens[static_cast<std::size_t>(c)].text) + " is not a finite decimal number");
    m.points.push_back(p);
  }
  while (m.faces.size() < faces) {
    if (!lines.next(tokens))
      refuseMeshLine(name, lines.line(), 1, "the file ends after " + std::to_string(m.faces.size()) + " of its " +
                                        std::to_string(faces) + " faces");
    std::uint64_t k = 0;
    if (!parseMeshUnsigned(tokens[0].text, k) || k < 1 || k > vertices)
      refuseMeshLine(name, lines.line(), tokens[0].column,
             "a face starts with its vertex count, 1 to " + std::to_string(vertices) + ", not " + quotedMeshToken(tokens[0].text));
    if (tokens.size() - 1 < k)
      refuseMeshLine(name, lines.line(), tokens[0].column,
             "a face of " + std::to_string(k) + " vertices needs " + std::to_string(k) + " indices; the line has " +
                 std::to_string(tokens.size() - 1));
    // Tokens after the indices are the face's colour, not used.
    std::vector<std::uint32_t> face(k);
    for (std::size_t i = 0; i < k; ++i) {
      std::uint64_t idx = 0;
      if (!parseMeshUnsigned(tokens[i + 1].text, idx) || idx >= vertices)
        refuseMeshLine(name, lines.line(), tokens[i + 1].column,
               "a vertex index is a plain number below " + std::to_string(vertices) + ", not " +
                   quotedMeshToken(tokens[i + 1].text));
      face[i] = static_cast<std::uint32_t>(idx);
    }
    m.faces.push_back(std::move(face));
  }
  return m;
}

}  // namespace mpr
