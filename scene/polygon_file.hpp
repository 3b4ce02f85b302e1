#pragma once
// What MPR's own mesh readers (off_reader, ply_reader) make of a file: its
// vertices and faces as written, before OpenMesh's importer builds the mesh.
#include <array>
#include <cstdint>
#include <vector>

namespace mpr {

struct PolygonFile {
  std::vector<std::array<float, 3>> points;
  // Each face's vertex indices, all below points.size(); faces of one or two
  // corners are kept (OpenMesh's importer skips them, as with its own readers).
  std::vector<std::vector<std::uint32_t>> faces;
};

}  // namespace mpr
