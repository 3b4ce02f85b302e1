#pragma once
// The buffers one implementation produced at one point of a script: what the
// conformance comparison looks at.
#include <cstdint>
#include <string>
#include <vector>

namespace mpr {

struct BufferSet {
  std::string point;                // "final" or the @snapshot name
  int width = 0, height = 0;
  std::vector<std::uint8_t> color;  // RGBA, rows from y = 0
  std::vector<std::uint32_t> depth; // stored 24-bit integers
  std::vector<std::uint8_t> stencil;
};

}  // namespace mpr
