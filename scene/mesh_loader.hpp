#pragma once
// Mesh files (OBJ, OFF, PLY, STL) through OpenMesh (OFF and PLY read by MPR,
// off_reader.hpp and ply_reader.hpp), as polygons with smooth
// vertex normals.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace mpr {

// The largest mesh file read (a regular file only): 512 MiB.
inline constexpr std::uint64_t kMaxMeshBytes = std::uint64_t{512} << 20;

// Throws std::runtime_error with the reason when the file cannot be read: not
// a regular file, over the size limit, header counts the file cannot hold,
// no faces, or a vertex that is not finite. What OpenMesh reported while
// reading (faces it dropped or changed) is added to `warnings` as MPR's own
// lines, never written to standard error.
Mesh loadMeshFile(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace mpr
