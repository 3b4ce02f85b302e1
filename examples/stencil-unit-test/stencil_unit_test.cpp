// A two-pass stencil technique, asserted per pixel on the emulated pipeline:
// capping the intersection of two rectangles (CSG by stencil, as a portal or
// a mirror would be masked). Pass 1 writes 1 inside rectangle A; pass 2
// increments, where the stencil is 1, inside rectangle B: the intersection
// holds 2, the rest of A 1, everything else 0.
#include <mpr/mpr.hpp>

namespace {

using mpr::testing::HasStencilPicture;
using mpr::testing::StencilAt;
using ::testing::Eq;

// An 8x8 window under identity matrices: NDC x = -1 .. 1 covers window x
// 0 .. 8; a pixel (x, y) is tested at its centre (x + 0.5, y + 0.5).
void intersect(mpr::GLContext& gl) {
  gl.clearStencil(0);
  gl.clear(GL_STENCIL_BUFFER_BIT);
  gl.enable(GL_STENCIL_TEST);
  gl.colorMask(false, false, false, false);
  // Pass 1: A = window x 0 .. 6, y 0 .. 4.
  gl.stencilFunc(GL_ALWAYS, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(-1.0f, -1.0f, 0.5f, 0.0f);
  // Pass 2: B = window x 4 .. 8, y 2 .. 8, only where pass 1 wrote.
  gl.stencilFunc(GL_EQUAL, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  gl.rectf(0.0f, -0.5f, 1.0f, 1.0f);
}

TEST(StencilIntersection, IntersectionHoldsTwo) {
  mpr::GLContext gl(8, 8, mpr::indigoProfile());
  intersect(gl);
  EXPECT_THAT(gl, StencilAt(4, 2, 2u));   // in A and B
  EXPECT_THAT(gl, StencilAt(3, 3, 1u));   // in A only
  EXPECT_THAT(gl, StencilAt(7, 7, 0u));   // in B only: pass 2's EQUAL 1 fails
  EXPECT_THAT(gl, StencilAt(6, 0, Eq(0u)));
}

TEST(StencilIntersection, WholeWindowAsAPicture) {
  mpr::GLContext gl(8, 8, mpr::indigoProfile());
  intersect(gl);
  // Rows top-down, from window y = 7 to y = 0.
  EXPECT_THAT(gl, HasStencilPicture(0, 0, R"(
      .  .  .  .  .  .  .  .
      .  .  .  .  .  .  .  .
      .  .  .  .  .  .  .  .
      .  .  .  .  .  .  .  .
      1  1  1  1  2  2  .  .
      1  1  1  1  2  2  .  .
      1  1  1  1  1  1  .  .
      1  1  1  1  1  1  .  .)"));
}

// The documentation's example (docs/reference/cpp-api.md), from outside the tree with the one include.
TEST(StencilReadme, ReplaceInsideTheSquare) {
  mpr::GLContext gl(16, 16, mpr::indigoProfile());
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 129, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(-0.5f, -0.5f, 0.5f, 0.5f);      // window 4 .. 12 both ways
  EXPECT_THAT(gl, mpr::testing::StencilAt(8, 8, 129u));
  EXPECT_THAT(gl, mpr::testing::HasStencilPicture(3, 3, R"(
      .   129   129
      .   129   129
      .     .     .)"));
}

// The buffer comparisons: a framebuffer equals itself.
TEST(StencilIntersection, BuffersEqualThemselves) {
  mpr::GLContext gl(8, 8, mpr::indigoProfile());
  intersect(gl);
  EXPECT_TRUE(mpr::testing::stencilBuffersEqual(gl.framebuffer(), gl.framebuffer()));
  EXPECT_TRUE(mpr::testing::depthBuffersEqual(gl.framebuffer(), gl.framebuffer()));
}

}  // namespace
