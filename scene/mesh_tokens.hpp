#pragma once
// The words of text mesh files (OFF, ASCII PLY) as MPR's readers take them:
// numbers in the grammar C++ streams read, which OpenMesh's readers used.
#include <cstdint>
#include <string>
#include <string_view>

namespace mpr {

inline bool isMeshBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

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

// The token for a message: quoted, control bytes as '?', cut at 40 bytes.
std::string quotedMeshToken(std::string_view token);

}  // namespace mpr
