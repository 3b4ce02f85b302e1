#pragma once
// Decomposition of GL's polygon primitives into triangles (GL 1.1 section
// 2.6.1), with the provoking vertex whose colour flat shading uses (GL 1.1
// Table 2.12: the last vertex of a triangle, the last of a quad, the first of a
// polygon). Diagonals follow Mesa (measured on llvmpipe with smooth colours):
// quads split (0,1,2)(0,2,3), quad-strip quads (2,0,3)(0,1,3) relative to
// their first vertex, polygons fan from vertex 0.
#include <array>
#include <cstdint>
#include <vector>

namespace mpr {

enum class PrimitiveType : std::uint8_t { Triangles, TriangleStrip, TriangleFan, Quads, QuadStrip, Polygon };

struct AssembledTriangle {
  std::array<std::uint32_t, 3> v;  // indices into the glBegin/glEnd vertex list
  std::uint32_t provoking;
};

// Incomplete trailing primitives are dropped, as GL requires.
std::vector<AssembledTriangle> assembleTriangles(PrimitiveType type, std::uint32_t count);

}  // namespace mpr
