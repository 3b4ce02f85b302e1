// Numbers in text mesh files (see mesh_tokens.hpp).
#include "scene/mesh_tokens.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace mpr {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

void splitMeshWords(std::string_view line, std::vector<MeshWord>& words) {
  words.clear();
  for (std::size_t i = 0; i < line.size();) {
    if (isMeshBlank(line[i])) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < line.size() && !isMeshBlank(line[i])) ++i;
    words.push_back({line.substr(start, i - start), start + 1});
  }
}

bool parseMeshUnsigned(std::string_view t, std::uint64_t& value) {
  if (t.empty() || t.size() > 10) return false;
  value = 0;
  for (char c : t) {
    if (!isDigit(c)) return false;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return value <= 0xffffffffu;
}

bool isMeshDecimal(std::string_view t) {
  std::size_t i = 0, digits = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  for (; i < t.size() && isDigit(t[i]); ++i) ++digits;
  if (i < t.size() && t[i] == '.')
    for (++i; i < t.size() && isDigit(t[i]); ++i) ++digits;
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    std::size_t exponentDigits = 0;
    for (; i < t.size() && isDigit(t[i]); ++i) ++exponentDigits;
    if (exponentDigits == 0) return false;
  }
  return i == t.size();
}

bool parseMeshFloat(std::string_view t, float& value) {
  if (!isMeshDecimal(t)) return false;
  const std::string text(t);
  value = std::strtof(text.c_str(), nullptr);
  return std::isfinite(value);
}

std::string quotedMeshToken(std::string_view t, std::size_t limit) {
  std::string s(t.substr(0, limit));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return "'" + s + (t.size() > limit ? "...'" : "'");
}

void refuseMeshLine(const std::string& name, std::uint64_t line, std::uint64_t column, const std::string& why) {
  throw std::runtime_error("mesh file '" + name + "' line " + std::to_string(line) + " column " +
                           std::to_string(column) + ": " + why);
}

void refuseMeshByte(const std::string& name, std::size_t byte, const std::string& why) {
  throw std::runtime_error("mesh file '" + name + "' byte " + std::to_string(byte) + ": " + why);
}

std::string meshCountsTooLarge(std::uint64_t vertices, std::uint64_t faces, std::size_t fileBytes) {
  return "claims " + std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces, more than its " +
         std::to_string(fileBytes) + " bytes can hold";
}

}  // namespace mpr
