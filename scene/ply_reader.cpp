// PLY files read element by element as their header declares (see ply_reader.hpp).
#include "scene/ply_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "scene/mesh_tokens.hpp"

namespace mpr {
namespace {

enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool scalarNamed(std::string_view t, Scalar& s) {
  static constexpr std::pair<std::string_view, Scalar> kNames[] = {
      {"char", Scalar::Int8},     {"uchar", Scalar::UInt8},    {"short", Scalar::Int16},   {"ushort", Scalar::UInt16},
      {"int", Scalar::Int32},     {"uint", Scalar::UInt32},    {"float", Scalar::Float32}, {"double", Scalar::Float64},
      {"int8", Scalar::Int8},     {"uint8", Scalar::UInt8},    {"int16", Scalar::Int16},   {"uint16", Scalar::UInt16},
      {"int32", Scalar::Int32},   {"uint32", Scalar::UInt32},  {"float32", Scalar::Float32}, {"float64", Scalar::Float64}};
  for (const auto& [n, v] : kNames)
    if (t == n) {
      s = v;
      return true;
    }
  return false;
}

std::size_t sizeOf(Scalar s) {
  switch (s) {
    case Scalar::Int8:
    case Scalar::UInt8: return 1;
    case Scalar::Int16:
    case Scalar::UInt16: return 2;
    case Scalar::Float64: return 8;
    default: return 4;
  }
}

bool isInteger(Scalar s) { return s != Scalar::Float32 && s != Scalar::Float64; }

struct Property {
  std::string name;
  bool list = false;
  Scalar count = Scalar::UInt8, value = Scalar::Float32;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Format { None, Ascii, LittleEndian, BigEndian };

class PlyParser {
 public:
  PlyParser(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  PolygonFile parse() {
    readHeader();
    const Element* vertexElement = nullptr;
    for (const Element& e : elements_) {
      if (e.name == "vertex") vertexElement = &e;
      if (e.name == "face") {
        if (!vertexElement) refuseLine(faceLine_, 1, "the face element comes before the vertex element");
        break;
      }
    }
    vertices_ = vertexElement ? vertexElement->count : 0;
    checkSizes();
    PolygonFile file;
    for (const Element& e : elements_) {
      readElement(e, file);
      if (e.name == "face") break;  // as OpenMesh: nothing after the faces is used
    }
    return file;
  }

 private:
  [[noreturn]] void refuseLine(std::uint64_t line, std::uint64_t column, const std::string& why) const {
    refuseMeshLine(name_, line, column, why);
  }
  [[noreturn]] void refuseByte(std::size_t byte, const std::string& why) const { refuseMeshByte(name_, byte, why); }

  // The header's lines up to end_header, each checked against PLY's grammar
  // (OpenMesh looped forever on a header without end_header and on lines it
  // did not know; found by fuzz/mesh_fuzzer).
  void readHeader() {
    std::size_t pos = 0;
    std::uint64_t lineNo = 0;
    bool ended = false;
    std::vector<MeshWord> words;
    while (pos < bytes_.size()) {
      const std::size_t end = std::min(bytes_.find('\n', pos), bytes_.size());
      std::string_view line = bytes_.substr(pos, end - pos);
      pos = end + 1;
      ++lineNo;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      splitMeshWords(line, words);
      if (lineNo == 1) {
        if (words.size() != 1 || words[0].text != "ply") refuseLine(1, 1, "does not start with ply");
        continue;
      }
      const std::string_view word = words.empty() ? std::string_view() : words[0].text;
      if (word == "end_header" && words.size() == 1) {
        ended = true;
        break;
      }
      if (word == "comment" || word == "obj_info") continue;
      if (word == "format") {
        if (format_ != Format::None || words.size() != 3 || words[2].text != "1.0" ||
            (words[1].text != "ascii" && words[1].text != "binary_little_endian" && words[1].text != "binary_big_endian"))
          refuseLine(lineNo, 1, "has a bad format line: " + quotedMeshToken(line, 80));
        format_ = words[1].text == "ascii" ? Format::Ascii
                  : words[1].text == "binary_little_endian" ? Format::LittleEndian
                                                       : Format::BigEndian;
        continue;
      }
      if (word == "property") {
        if (elements_.empty()) refuseLine(lineNo, 1, "has a property before any element: " + quotedMeshToken(line, 80));
        Property p;
        const bool ok = words.size() >= 3 && words[1].text == "list"
                            ? words.size() == 5 && scalarNamed(words[2].text, p.count) && scalarNamed(words[3].text, p.value)
                            : words.size() == 3 && scalarNamed(words[1].text, p.value);
        if (!ok) refuseLine(lineNo, 1, "has a bad property line: " + quotedMeshToken(line, 80));
        p.list = words[1].text == "list";
        p.name = std::string(words.back().text);
        if (p.list && !isInteger(p.count))
          refuseLine(lineNo, 1, "a list's count must have an integer type: " + quotedMeshToken(line, 80));
        Element& e = elements_.back();
        const bool indices = e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
        if (indices && (!p.list || !isInteger(p.value)))
          refuseLine(lineNo, 1, "a face's vertex indices are a list of integers: " + quotedMeshToken(line, 80));
        if (e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z") && p.list)
          refuseLine(lineNo, 1, "a vertex coordinate is one number, not a list: " + quotedMeshToken(line, 80));
        e.properties.push_back(p);
        continue;
      }
      if (word != "element") refuseLine(lineNo, 1, "has a header line PLY does not know: " + quotedMeshToken(line, 80));
      Element e;
      if (words.size() != 3 || !parseMeshUnsigned(words[2].text, e.count))
        refuseLine(lineNo, 1, "has an element line without a count: " + quotedMeshToken(line, 80));
      e.name = std::string(words[1].text);
      for (const Element& other : elements_)
        if (other.name == e.name) refuseLine(lineNo, 1, "has a second '" + e.name + "' element");
      if (e.name == "face") faceLine_ = lineNo;
      elements_.push_back(std::move(e));
    }
    if (!ended) refuseLine(lineNo, 1, "has no end_header line closing its header");
    if (format_ == Format::None) refuseLine(lineNo, 1, "has no format line");
    for (const Element& e : elements_)
      if (e.name == "vertex")
        for (const char* axis : {"x", "y", "z"})
          if (std::none_of(e.properties.begin(), e.properties.end(), [&](const Property& p) { return p.name == axis; }))
            refuseLine(lineNo, 1, std::string("its vertex element has no '") + axis + "' property");
    body_ = std::min(pos, bytes_.size());
    bodyLine_ = lineNo + 1;
  }

  // Every element item takes at least a byte per value in binary (two in
  // ASCII: the value and a blank), so a 40-byte file cannot have 2e9 vertices
  // reserved for it.
  // The refusal names the element whose count the bytes cannot hold: an
  // "element edge 2000000000" was reported as the vertex and face counts.
  void checkSizes() const {
    const std::uint64_t left = bytes_.size() - body_ + (format_ == Format::Ascii ? 1 : 0);
    std::uint64_t needed = 0, faces = 0;
    for (const Element& e : elements_)
      if (e.name == "face") faces = e.count;
    const Element* over = nullptr;
    bool before = false;  // earlier elements take bytes too
    for (const Element& e : elements_) {
      std::uint64_t item = 0;
      for (const Property& p : e.properties)
        item += format_ == Format::Ascii ? 2 : sizeOf(p.list ? p.count : p.value);
      before = needed > 0;
      needed += e.count * std::max<std::uint64_t>(item, 1);  // below 2^32 * 2^40: no overflow
      if (needed > left || e.count > left) {
        over = &e;
        break;
      }
    }
    if (over && over->name != "vertex" && over->name != "face")
      refuseLine(bodyLine_, 1, "its element '" + over->name + "' claims " + std::to_string(over->count) +
                                   " items, more than its " + std::to_string(bytes_.size()) + " bytes can hold" +
                                   (before ? " after the elements before it" : ""));
    if (over || vertices_ > left || faces > left)
      refuseLine(bodyLine_, 1, meshCountsTooLarge(vertices_, faces, bytes_.size()));
  }

  void readElement(const Element& e, PolygonFile& file) {
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    if (isVertex) file.points.reserve(e.count);
    if (isFace) file.faces.reserve(e.count);
    for (std::uint64_t item = 0; item < e.count; ++item) {
      std::array<float, 3> point{};
      std::vector<std::uint32_t> face;
      for (const Property& p : e.properties) {
        const int axis = !isVertex ? -1 : p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
        if (!p.list) {
          if (axis >= 0) point[static_cast<std::size_t>(axis)] = readCoordinate(p.value, e, item);
          else skipValue(p.value, e, item);
          continue;
        }
        const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
        const std::uint64_t count = readCount(p, e, item, indices);
        for (std::uint64_t i = 0; i < count; ++i) {
          if (indices) face.push_back(readIndex(p.value, e, item));
          else skipValue(p.value, e, item);
        }
      }
      if (isVertex) file.points.push_back(point);
      if (isFace) file.faces.push_back(std::move(face));
    }
  }

  // --- ASCII: the body as whitespace-separated words, their line and column kept.
  struct Word {
    std::string_view text;
    std::uint64_t line, column;
  };

  Word nextWord(const Element& e, std::uint64_t item) {
    while (at_ < bytes_.size()) {
      const char c = bytes_[at_];
      if (c == '\n') {
        ++wordLine_;
        lineStart_ = ++at_;
        continue;
      }
      if (isMeshBlank(c)) {
        ++at_;
        continue;
      }
      const std::size_t start = at_;
      while (at_ < bytes_.size() && bytes_[at_] != '\n' && !isMeshBlank(bytes_[at_])) ++at_;
      return {bytes_.substr(start, at_ - start), wordLine_, start - lineStart_ + 1};
    }
    refuseLine(wordLine_, at_ - lineStart_ + 1,
               "the file ends inside " + e.name + " " + std::to_string(item) + " of " + std::to_string(e.count));
  }

  void startAscii() {
    if (started_) return;
    started_ = true;
    at_ = lineStart_ = body_;
    wordLine_ = bodyLine_;
  }

  // --- binary: values of the file's byte order.
  std::uint64_t readBits(std::size_t size, const Element& e, std::uint64_t item) {
    if (!started_) {
      started_ = true;
      at_ = body_;
    }
    if (bytes_.size() - at_ < size)
      refuseByte(at_, "the file ends inside " + e.name + " " + std::to_string(item) + " of " + std::to_string(e.count));
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const std::size_t b = format_ == Format::LittleEndian ? size - 1 - i : i;
      v = (v << 8) | static_cast<unsigned char>(bytes_[at_ + b]);
    }
    at_ += size;
    return v;
  }

  // A binary value as a double (integers exactly).
  double readBinary(Scalar s, const Element& e, std::uint64_t item) {
    const std::uint64_t bits = readBits(sizeOf(s), e, item);
    switch (s) {
      case Scalar::Int8: return static_cast<std::int8_t>(bits);
      case Scalar::UInt8: return static_cast<std::uint8_t>(bits);
      case Scalar::Int16: return static_cast<std::int16_t>(bits);
      case Scalar::UInt16: return static_cast<std::uint16_t>(bits);
      case Scalar::Int32: return static_cast<std::int32_t>(bits);
      case Scalar::UInt32: return static_cast<std::uint32_t>(bits);
      case Scalar::Float32: {
        float f;
        const auto b32 = static_cast<std::uint32_t>(bits);
        std::memcpy(&f, &b32, sizeof f);
        return f;
      }
      case Scalar::Float64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
    }
    return 0.0;
  }

  float readCoordinate(Scalar s, const Element& e, std::uint64_t item) {
    if (format_ == Format::Ascii) {
      startAscii();
      const Word w = nextWord(e, item);
      float f = 0.0f;
      if (!parseMeshFloat(w.text, f))
        refuseLine(w.line, w.column, quotedMeshToken(w.text) + " is not a finite decimal number");
      return f;
    }
    const std::size_t byte = started_ ? at_ : body_;
    // OpenMesh: float32 as it is, float64 rounded to float.
    const float f = static_cast<float>(readBinary(s, e, item));
    if (!std::isfinite(f)) refuseByte(byte, "vertex " + std::to_string(item) + " has a coordinate that is not finite");
    return f;
  }

  void skipValue(Scalar s, const Element& e, std::uint64_t item) {
    if (format_ != Format::Ascii) {
      (void)readBits(sizeOf(s), e, item);
      return;
    }
    startAscii();
    const Word w = nextWord(e, item);
    if (!isMeshDecimal(w.text)) refuseLine(w.line, w.column, quotedMeshToken(w.text) + " is not a number");
  }

  // A list's length: a plain count the rest of the file can hold (and, for a
  // face's corners, at most the vertex count).
  std::uint64_t readCount(const Property& p, const Element& e, std::uint64_t item, bool indices) {
    const std::uint64_t bound = indices ? vertices_ : std::numeric_limits<std::uint64_t>::max();
    if (format_ == Format::Ascii) {
      startAscii();
      const Word w = nextWord(e, item);
      std::uint64_t n = 0;
      if (!parseMeshUnsigned(w.text, n) || n > bound || n > bytes_.size() - at_ + 1)
        refuseLine(w.line, w.column,
                   "a list's length is a plain number " + std::string(indices ? "up to the vertex count " + std::to_string(vertices_) : "the file can hold") +
                       ", not " + quotedMeshToken(w.text));
      return n;
    }
    const std::size_t byte = started_ ? at_ : body_;
    const double n = readBinary(p.count, e, item);
    if (n < 0 || n > static_cast<double>(bound) || n * static_cast<double>(sizeOf(p.value)) > static_cast<double>(bytes_.size() - at_))
      refuseByte(byte, e.name + " " + std::to_string(item) + " has a list of " + std::to_string(static_cast<long long>(n)) +
                           " values, more than " + (indices ? "its vertices or " : "") + "the file holds");
    return static_cast<std::uint64_t>(n);
  }

  std::uint32_t readIndex(Scalar s, const Element& e, std::uint64_t item) {
    if (format_ == Format::Ascii) {
      startAscii();
      const Word w = nextWord(e, item);
      std::uint64_t idx = 0;
      if (!parseMeshUnsigned(w.text, idx) || idx >= vertices_)
        refuseLine(w.line, w.column,
                   "a vertex index is a plain number below " + std::to_string(vertices_) + ", not " + quotedMeshToken(w.text));
      return static_cast<std::uint32_t>(idx);
    }
    const std::size_t byte = started_ ? at_ : body_;
    const double idx = readBinary(s, e, item);
    if (idx < 0 || idx >= static_cast<double>(vertices_))
      refuseByte(byte, "face " + std::to_string(item) + " names vertex " + std::to_string(static_cast<long long>(idx)) +
                           " of " + std::to_string(vertices_));
    return static_cast<std::uint32_t>(idx);
  }

  std::string_view bytes_;
  const std::string& name_;
  Format format_ = Format::None;
  std::vector<Element> elements_;
  std::uint64_t faceLine_ = 0, vertices_ = 0;
  std::size_t body_ = 0;
  std::uint64_t bodyLine_ = 0;
  // The read position in the body.
  bool started_ = false;
  std::size_t at_ = 0, lineStart_ = 0;
  std::uint64_t wordLine_ = 0;
};

}  // namespace

PolygonFile parsePly(std::string_view bytes, const std::string& name) { return PlyParser(bytes, name).parse(); }

}  // namespace mpr
