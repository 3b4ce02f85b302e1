#pragma once
// The words of text mesh files (OFF, ASCII PLY) as MPR's readers take them:
// numbers in the grammar C++ streams read, which OpenMesh's readers used;
// and the readers' refusals.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mpr {

inline bool isMeshBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// A word of a line and its 1-based column, in bytes.
struct MeshWord {
  std::string_view text;
  std::uint64_t column;
};

// The line's blank-separated words, into `words` (cleared first).
void splitMeshWords(std::string_view line, std::vector<MeshWord>& words);

// Plain decimal digits, at most 2^32 - 1 (OpenMesh's unsigned int); false
// otherwise (a sign, a point, anything else).
bool parseMeshUnsigned(std::string_view token, std::uint64_t& value);

// Whether the token is a decimal number as `stream >> float` reads one (the
// num_get grammar: sign, digits with at most one point, an exponent with
// digits); no hex, inf or nan.
bool isMeshDecimal(std::string_view token);

// A coordinate as OpenMesh read it (`stream >> float`: strtof, correctly
// rounded); false when the token is not a decimal or not finite as a float.
bool parseMeshFloat(std::string_view token, float& value);

// The token (or line) for a message: quoted, control bytes as '?', cut at
// `limit` bytes.
std::string quotedMeshToken(std::string_view token, std::size_t limit = 40);

// Refusals: std::runtime_error "mesh file 'NAME' line L column C: why", or
// "... byte B: why" in a binary file.
[[noreturn]] void refuseMeshLine(const std::string& name, std::uint64_t line, std::uint64_t column,
                                 const std::string& why);
[[noreturn]] void refuseMeshByte(const std::string& name, std::size_t byte, const std::string& why);

// Why a header's counts are refused before anything is reserved for them.
std::string meshCountsTooLarge(std::uint64_t vertices, std::uint64_t faces, std::size_t fileBytes);

}  // namespace mpr
