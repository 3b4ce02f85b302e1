#include "algorithms/quad_to_quad.hpp"

#include <cmath>
#include <string>

namespace mpr {
namespace {

// The paper writes M with rows (a d g) (b e h) (c f i); GLM stores columns,
// so M(row, col) is m[col][row].
double& at(DMat3& m, int row, int col) { return m[col][row]; }

double cross(DVec2 o, DVec2 a, DVec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

void checkQuad(const Quad& q) {
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(q[i].x) || !std::isfinite(q[i].y))
      throw DegenerateQuadError("quad corner " + std::to_string(i) + " is not finite");
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (q[i] == q[j])
        throw DegenerateQuadError("quad corners " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
  // Convex and non-degenerate: every turn has the same strict sign.
  double sign = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double t = cross(q[i], q[(i + 1) % 4], q[(i + 2) % 4]);
    if (t == 0.0)
      throw DegenerateQuadError("quad corners " + std::to_string(i) + ", " + std::to_string((i + 1) % 4) + " and " +
                                std::to_string((i + 2) % 4) + " are collinear");
    if (sign != 0.0 && (t > 0.0) != (sign > 0.0))
      throw DegenerateQuadError("quad is not convex (or its edges cross)");
    sign = t;
  }
}

}  // namespace

DMat3 squareToQuad(const Quad& q) {
  checkQuad(q);
  const double sx = q[0].x - q[1].x + q[2].x - q[3].x;
  const double sy = q[0].y - q[1].y + q[2].y - q[3].y;
  DMat3 m(0.0);
  at(m, 2, 0) = q[0].x;  // c
  at(m, 2, 1) = q[0].y;  // f
  at(m, 2, 2) = 1.0;     // i
  if (sx == 0.0 && sy == 0.0) {
    // Affine: a parallelogram (g = h = 0).
    at(m, 0, 0) = q[1].x - q[0].x;
    at(m, 1, 0) = q[2].x - q[1].x;
    at(m, 0, 1) = q[1].y - q[0].y;
    at(m, 1, 1) = q[2].y - q[1].y;
    return m;
  }
  // (A2): g and h by Cramer's rule.
  const double dx1 = q[1].x - q[2].x, dx2 = q[3].x - q[2].x;
  const double dy1 = q[1].y - q[2].y, dy2 = q[3].y - q[2].y;
  const double den = dx1 * dy2 - dx2 * dy1;
  const double g = (sx * dy2 - dx2 * sy) / den;
  const double h = (dx1 * sy - sx * dy1) / den;
  // (A3)
  at(m, 0, 0) = q[1].x - q[0].x + g * q[1].x;  // a
  at(m, 1, 0) = q[3].x - q[0].x + h * q[3].x;  // b
  at(m, 0, 1) = q[1].y - q[0].y + g * q[1].y;  // d
  at(m, 1, 1) = q[3].y - q[0].y + h * q[3].y;  // e
  at(m, 0, 2) = g;
  at(m, 1, 2) = h;
  return m;
}

DMat3 quadToSquare(const Quad& q) {
  // The adjoint (adjugate) of the square-to-quad map: its inverse up to scale,
  // which a projective map does not see.
  const DMat3 m = squareToQuad(q);
  DMat3 adj(0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      // adj(r, c) = cofactor(c, r)
      adj[c][r] = m[c1][r1] * m[c2][r2] - m[c2][r1] * m[c1][r2];
    }
  return adj;
}

DMat3 quadToQuad(const Quad& from, const Quad& to) { return quadToSquare(from) * squareToQuad(to); }

DVec2 applyProjectiveMap(const DMat3& m, DVec2 p) {
  const glm::dvec3 r = glm::dvec3(p.x, p.y, 1.0) * m;  // row vector times M
  return DVec2(r.x / r.z, r.y / r.z);
}

Mat4 quadToQuadMatrix4(const DMat3& m) {
  // (A5) in the paper's row-vector form, transposed for GL's column vectors:
  // x' = a x + b y + c, y' = d x + e y + f, z' = 0, w' = g x + h y + i.
  Mat4 g(0.0f);
  for (int out = 0; out < 2; ++out) {
    g[0][out] = static_cast<float>(m[out][0]);
    g[1][out] = static_cast<float>(m[out][1]);
    g[3][out] = static_cast<float>(m[out][2]);
  }
  g[0][3] = static_cast<float>(m[2][0]);
  g[1][3] = static_cast<float>(m[2][1]);
  g[3][3] = static_cast<float>(m[2][2]);
  return g;
}

}  // namespace mpr
