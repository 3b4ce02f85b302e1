// The mesh readers (OpenMesh behind MPR's checks): the input is written to a
// file whose extension the first byte picks (.off .ply .obj .stl), then
// loaded; a refusal is a std::runtime_error, never a crash or a huge
// allocation.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "scene/mesh_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kExt[] = {".off", ".ply", ".obj", ".stl"};
  const std::string path = "/tmp/mpr-mesh-fuzz-" + std::to_string(getpid()) + kExt[data[0] % 4];
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  } else {
    return 0;
  }
  try {
    (void)mpr::loadMeshFile(path);
  } catch (const std::runtime_error&) {
  }
  std::remove(path.c_str());
  return 0;
}
