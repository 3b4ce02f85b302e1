#pragma once
// PLY mesh files, read by MPR itself and handed to OpenMesh's importer as
// OpenMesh's PLY reader hands them for the files it reads correctly: the
// vertices' x, y, z as floats (ASCII text through strtof, binary float32
// as it is, float64 rounded to float) and the faces' vertex_indices (or
// vertex_index) in order.
//
// Why not OpenMesh's reader: it takes a list's count as an unsigned int
// from any text, so a face "-3 0 1 2" asked for 2^32 - 3 indices (16 GB), a
// binary uint count likewise; it reads other lists as one value and loses
// its place; it loops on headers it does not know (found by
// fuzz/mesh_fuzzer). Here every element follows the header exactly (lists
// skipped whole), every count is checked against the bytes left before
// anything is reserved, and a refusal names the line and column (binary: the
// byte).
#include <string>
#include <string_view>

#include "scene/polygon_file.hpp"

namespace mpr {

// Parses the bytes of a PLY file; `name` is the file as messages give it.
// Throws std::runtime_error "mesh file 'NAME' line L column C: why".
PolygonFile parsePly(std::string_view bytes, const std::string& name);

}  // namespace mpr
