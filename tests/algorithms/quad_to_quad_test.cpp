// The quad-to-quad projective map of the 1994 paper's Appendix (A1)-(A5).
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "algorithms/quad_to_quad.hpp"
#include "pipeline/gl/gl_context.hpp"

namespace mpr {
namespace {

const Quad kUnit = {DVec2(0, 0), DVec2(1, 0), DVec2(1, 1), DVec2(0, 1)};

void expectNear(DVec2 a, DVec2 b, double tol, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
}

TEST(QuadToQuad, SquareToQuadMapsTheCorners) {
  const Quad quads[] = {
      kUnit,
      {DVec2(2, 1), DVec2(6, 2), DVec2(7, 5), DVec2(3, 4)},        // parallelogram (affine)
      {DVec2(0, 0), DVec2(4, 0), DVec2(3, 2), DVec2(1, 2)},        // trapezoid (projective)
      {DVec2(-3, 1), DVec2(5, -2), DVec2(9, 7), DVec2(-1, 4.5)},   // general convex
  };
  for (const Quad& q : quads) {
    const DMat3 m = squareToQuad(q);
    for (int i = 0; i < 4; ++i) expectNear(applyProjectiveMap(m, kUnit[i]), q[i], 1e-12, "corner " + std::to_string(i));
  }
  // A parallelogram is affine: g = h = 0 (third column of the paper's M).
  const DMat3 affine = squareToQuad(quads[1]);
  EXPECT_EQ(affine[2][0], 0.0);
  EXPECT_EQ(affine[2][1], 0.0);
  // The unit square maps by the identity.
  EXPECT_EQ(squareToQuad(kUnit), DMat3(1.0));
}

TEST(QuadToQuad, AdjointInvertsAndQuadToQuadMapsCornerToCorner) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  for (int trial = 0; trial < 200; ++trial) {
    // Random convex quads: a jittered square, scaled and moved.
    auto randomQuad = [&] {
      Quad q = {DVec2(0 + jitter(rng), 0 + jitter(rng)), DVec2(3 + jitter(rng), 0 + jitter(rng)),
                DVec2(3 + jitter(rng), 3 + jitter(rng)), DVec2(0 + jitter(rng), 3 + jitter(rng))};
      for (DVec2& p : q) p = p * 10.0 + DVec2(-7, 4);
      return q;
    };
    const Quad from = randomQuad(), to = randomQuad();
    // Round trip through the square.
    const DMat3 sq = squareToQuad(from), qs = quadToSquare(from);
    const DVec2 p(0.3, 0.8);
    expectNear(applyProjectiveMap(qs, applyProjectiveMap(sq, p)), p, 1e-10, "round trip");
    for (int i = 0; i < 4; ++i) expectNear(applyProjectiveMap(qs, from[i]), kUnit[i], 1e-10, "to square");
    const DMat3 qq = quadToQuad(from, to);
    for (int i = 0; i < 4; ++i) expectNear(applyProjectiveMap(qq, from[i]), to[i], 1e-9, "quad to quad");
  }
}

TEST(QuadToQuad, DegenerateQuadsAreRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Quad bad[] = {
      {DVec2(0, 0), DVec2(1, 0), DVec2(2, 0), DVec2(0, 1)},   // three collinear corners
      {DVec2(0, 0), DVec2(1, 0), DVec2(1, 0), DVec2(0, 1)},   // repeated corner
      {DVec2(0, 0), DVec2(0, 0), DVec2(0, 0), DVec2(0, 0)},   // zero area
      {DVec2(0, 0), DVec2(1, 0), DVec2(0, 1), DVec2(1, 1)},   // bow-tie (edges cross)
      {DVec2(0, 0), DVec2(4, 0), DVec2(1, 1), DVec2(0, 4)},   // non-convex (dart)
      {DVec2(nan, 0), DVec2(1, 0), DVec2(1, 1), DVec2(0, 1)},
      {DVec2(0, 0), DVec2(inf, 0), DVec2(1, 1), DVec2(0, 1)},
  };
  for (const Quad& q : bad) {
    EXPECT_THROW(squareToQuad(q), DegenerateQuadError);
    EXPECT_THROW(quadToQuad(kUnit, q), DegenerateQuadError);
  }
  try {
    squareToQuad(bad[0]);
  } catch (const DegenerateQuadError& e) {
    EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
  }
}

TEST(QuadToQuad, Matrix4ZeroesDepthAndMatchesTheThreeByThree) {
  const Quad to = {DVec2(-3, 1), DVec2(5, -2), DVec2(9, 7), DVec2(-1, 4.5)};
  const DMat3 m = squareToQuad(to);
  const Mat4 g = quadToQuadMatrix4(m);
  for (float z : {-5.0f, 0.0f, 0.25f, 100.0f}) {
    for (const DVec2& p : kUnit) {
      const Vec4 r = g * Vec4(static_cast<float>(p.x), static_cast<float>(p.y), z, 1.0f);
      EXPECT_EQ(r.z, 0.0f) << "z is sent to 0 (A5)";
      const DVec2 expected = applyProjectiveMap(m, p);
      EXPECT_NEAR(r.x / r.w, expected.x, 1e-5);
      EXPECT_NEAR(r.y / r.w, expected.y, 1e-5);
    }
  }
  // The z row and column are zero.
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(g[2][i], 0.0f);
    EXPECT_EQ(g[i][2], 0.0f);
  }
}

TEST(QuadToQuad, MatrixOnTheGLStackMapsCorners) {
  // The unit square drawn through the (A5) matrix lands on the target quad:
  // pixel centres just inside each target corner are covered, the z column is
  // zeroed so depth is the same everywhere.
  GLContext gl(32, 32, indigoProfile());
  // Object coordinates are window coordinates.
  gl.matrixMode(GL_PROJECTION);
  gl.ortho(0, 32, 0, 32, -1, 1);
  gl.matrixMode(GL_MODELVIEW);
  const Quad unit = {DVec2(0, 0), DVec2(1, 0), DVec2(1, 1), DVec2(0, 1)};
  const Quad target = {DVec2(4, 4), DVec2(28, 8), DVec2(24, 28), DVec2(6, 20)};
  const Mat4 m = quadToQuadMatrix4(quadToQuad(unit, target));
  gl.multMatrix(&m[0][0]);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 9, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.begin(GL_QUADS);
  gl.vertex4f(0, 0, 0.7f, 1);
  gl.vertex4f(1, 0, 0.7f, 1);
  gl.vertex4f(1, 1, 0.7f, 1);
  gl.vertex4f(0, 1, 0.7f, 1);
  gl.end();
  EXPECT_EQ(gl.stencilAt(5, 5), 9u);
  EXPECT_EQ(gl.stencilAt(26, 8), 9u);
  EXPECT_EQ(gl.stencilAt(23, 26), 9u);
  EXPECT_EQ(gl.stencilAt(6, 19), 9u);
  EXPECT_EQ(gl.stencilAt(3, 3), 0u);
  EXPECT_EQ(gl.stencilAt(29, 8), 0u);
  EXPECT_EQ(gl.stencilAt(16, 2), 0u);
}

}  // namespace
}  // namespace mpr
