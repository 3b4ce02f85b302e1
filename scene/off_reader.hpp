#pragma once
// OFF mesh files, read by MPR itself and handed to OpenMesh's importer as
// OpenMesh's own OFF reader would hand them: the same vertices (three floats
// read as C++ streams read them), the same faces in the same order.
//
// Why not OpenMesh's reader: it reads faces as one token stream across lines,
// so a stray token on one face line shifts every face after it, and a "-3"
// then read as an unsigned vertex count asks for 2^32 - 3 indices (2 GB; found
// by fuzz/mesh_fuzzer, twice in different shapes). Here a vertex or face is
// one line, every count and index is checked against the file before anything
// is reserved, and a refusal names the line and column.
//
// Accepted: ASCII [ST][C][N]OFF (a vertex line's first three numbers are its
// position; normals, colours and texture coordinates after them are not
// used), counts on the OFF line or the lines after it, '#' comments anywhere;
// and binary "OFF BINARY" (OpenMesh's little-endian layout: uint32 counts,
// float32 positions, uint32 face sizes and indices).
#include <string>
#include <string_view>

#include "scene/polygon_file.hpp"

namespace mpr {

// Parses the bytes of an OFF file; `name` is the file as messages give it.
// Throws std::runtime_error "mesh file 'NAME' line L column C: why" (binary:
// "byte B").
PolygonFile parseOff(std::string_view bytes, const std::string& name);

}  // namespace mpr
