// Numbers in text mesh files (see mesh_tokens.hpp).
#include "scene/mesh_tokens.hpp"

#include <cmath>
#include <cstdlib>

namespace mpr {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

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

std::string quotedMeshToken(std::string_view t) {
  std::string s(t.substr(0, 40));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return "'" + s + (t.size() > 40 ? "...'" : "'");
}

}  // namespace mpr
