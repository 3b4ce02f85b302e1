#pragma once
// The projective map of one quadrilateral onto another, 1994 paper Appendix:
// square-to-quad (A1-A3, Heckbert's construction), its adjoint for
// quad-to-square, their product for quad-to-quad, and the 4x4 form (A5) with a
// zeroed Z column that can be loaded on a GL matrix stack.
//
// Convention of the paper: row vectors, [x y w] = [u v 1] * M.
#include <array>
#include <stdexcept>

#include "util/vecmath.hpp"

namespace mpr {

using Quad = std::array<DVec2, 4>;  // corners in order (0,0) (1,0) (1,1) (0,1) of the unit square

class DegenerateQuadError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// M_sq of (A1)-(A3): maps the unit square corners (0,0) (1,0) (1,1) (0,1) onto
// quad[0..3]. Throws DegenerateQuadError when the quad is degenerate (three
// collinear corners, zero area, a non-finite coordinate, or not convex).
DMat3 squareToQuad(const Quad& quad);
// The inverse map, computed as the adjoint of squareToQuad (the paper: "the two
// mappings are adjoints of each other").
DMat3 quadToSquare(const Quad& quad);
// Maps `from` corner i onto `to` corner i: quadToSquare(from) * squareToQuad(to).
DMat3 quadToQuad(const Quad& from, const Quad& to);

// Applies a 3x3 map in the paper's row-vector convention; returns (x/w, y/w).
DVec2 applyProjectiveMap(const DMat3& m, DVec2 p);

// (A5): the 4x4 GL matrix (column-major, for glLoadMatrix / glMultMatrix,
// acting on column vectors) whose action on (x, y, z, 1) is the 3x3 map on
// (x, y) with z sent to 0: "clears depth values".
Mat4 quadToQuadMatrix4(const DMat3& m);

}  // namespace mpr
