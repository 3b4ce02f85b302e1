#pragma once
// Mesh files (OBJ, OFF, PLY, STL) through OpenMesh, as polygons with smooth
// vertex normals.
#include <string>

#include "scene/scene.hpp"

namespace mpr {

// Throws std::runtime_error with the reason when the file cannot be read.
Mesh loadMeshFile(const std::string& path);

}  // namespace mpr
