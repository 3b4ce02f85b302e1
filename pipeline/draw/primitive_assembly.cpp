#include "pipeline/draw/primitive_assembly.hpp"

namespace mpr {

std::vector<AssembledTriangle> assembleTriangles(PrimitiveType type, std::uint32_t n) {
  std::vector<AssembledTriangle> out;
  switch (type) {
    case PrimitiveType::Triangles:
      for (std::uint32_t i = 0; i + 2 < n; i += 3) out.push_back({{i, i + 1, i + 2}, i + 2});
      break;
    case PrimitiveType::TriangleStrip:
      // Odd triangles swap their first two vertices to keep one winding.
      for (std::uint32_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 0)
          out.push_back({{i, i + 1, i + 2}, i + 2});
        else
          out.push_back({{i + 1, i, i + 2}, i + 2});
      }
      break;
    case PrimitiveType::TriangleFan:
      for (std::uint32_t i = 1; i + 1 < n; ++i) out.push_back({{0, i, i + 1}, i + 1});
      break;
    case PrimitiveType::Quads:
      for (std::uint32_t i = 0; i + 3 < n; i += 4) {
        out.push_back({{i, i + 1, i + 2}, i + 3});
        out.push_back({{i, i + 2, i + 3}, i + 3});
      }
      break;
    case PrimitiveType::QuadStrip:
      // Quad k is (2k, 2k+1, 2k+3, 2k+2); flat colour from vertex 2k+3.
      for (std::uint32_t i = 0; i + 3 < n; i += 2) {
        out.push_back({{i + 2, i, i + 3}, i + 3});
        out.push_back({{i, i + 1, i + 3}, i + 3});
      }
      break;
    case PrimitiveType::Polygon:
      for (std::uint32_t i = 1; i + 1 < n; ++i) out.push_back({{i, i + 1, 0}, 0});
      break;
  }
  return out;
}

}  // namespace mpr
