// The end-of-pipeline map (GLContext::setWindowMap): the 1994 paper's wished
// hardware stage, a 3x3 projective map of normalised device x, y applied
// after the perspective divide, which keeps depth ("Refractions").
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "pipeline/gl/gl_context.hpp"
#include "algorithms/quad_to_quad.hpp"

namespace mpr {
namespace {

constexpr int kSide = 32;

// A perspective view of a sloped, coloured triangle and a quad facing the
// camera at z = -2, stencil 7 where drawn.
void drawScene(GLContext& gl) {
  gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  gl.enable(GL_DEPTH_TEST);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 7, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.begin(GL_TRIANGLES);
  gl.color4f(1, 0, 0, 1);
  gl.vertex4f(-1.5f, -1.2f, -1.5f, 1.0f);
  gl.color4f(0, 1, 0, 1);
  gl.vertex4f(1.4f, -0.9f, -3.5f, 1.0f);
  gl.color4f(0, 0, 1, 1);
  gl.vertex4f(0.2f, 1.3f, -2.5f, 1.0f);
  gl.end();
  gl.color4f(1, 1, 1, 1);
  gl.begin(GL_QUADS);
  gl.vertex4f(-0.5f, -0.5f, -2.0f, 1.0f);
  gl.vertex4f(0.5f, -0.5f, -2.0f, 1.0f);
  gl.vertex4f(0.5f, 0.5f, -2.0f, 1.0f);
  gl.vertex4f(-0.5f, 0.5f, -2.0f, 1.0f);
  gl.end();
}

GLContext perspectiveContext() {
  GLContext gl(kSide, kSide, indigoProfile());
  gl.matrixMode(GL_PROJECTION);
  gl.frustum(-0.1, 0.1, -0.1, 0.1, 0.1, 10.0);
  gl.matrixMode(GL_MODELVIEW);
  return gl;
}

// The identity map puts every vertex where it was and clips at the view
// volume's own sides: coverage is the same. Depth and colour are then
// interpolated by the stage's own arithmetic (barycentric weights over 1/q,
// in double) instead of llvmpipe's single-precision planes, so the stored
// integers may differ in the last unit, never more.
TEST(WindowMap, IdentityChangesNoCoverageOrColour) {
  GLContext plain = perspectiveContext(), mapped = perspectiveContext();
  mapped.setWindowMap(glm::mat3(1.0f));
  drawScene(plain);
  drawScene(mapped);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      EXPECT_EQ(mapped.stencilAt(x, y), plain.stencilAt(x, y)) << x << "," << y;
      const Rgba8 a = mapped.colorAt(x, y), b = plain.colorAt(x, y);
      for (int c = 0; c < 4; ++c) EXPECT_LE(std::abs(int(a[c]) - int(b[c])), 1) << x << "," << y << " channel " << c;
      const long d = static_cast<long>(mapped.depthAt(x, y)) - static_cast<long>(plain.depthAt(x, y));
      EXPECT_LE(std::labs(d), 1) << x << "," << y;
    }
}

// A projective map keeps depth: the quad facing the camera has one depth
// everywhere unmapped, and keeps exactly that depth on every pixel it covers
// through the 3x3 stage. Loaded instead as the 4x4 of (A5) with Z kept (MPR's
// GL-expressible default), depth is divided by the map's w and varies across
// the quad. The quad lands where the map sends its corners.
TEST(WindowMap, AProjectiveMapKeepsDepth) {
  const Quad from = {DVec2(-0.25, -0.25), DVec2(0.25, -0.25), DVec2(0.25, 0.25), DVec2(-0.25, 0.25)};
  const Quad to = {DVec2(-0.8, -0.6), DVec2(0.7, -0.9), DVec2(0.5, 0.8), DVec2(-0.6, 0.4)};
  DMat3 map = quadToQuad(from, to);
  map /= map[2][2];

  GLContext plain = perspectiveContext();
  drawScene(plain);
  const std::uint32_t quadDepth = plain.depthAt(kSide / 2, kSide / 2);

  GLContext stage = perspectiveContext();
  stage.setWindowMap(glm::mat3(map));
  drawScene(stage);
  GLContext kept(kSide, kSide, indigoProfile());
  kept.matrixMode(GL_PROJECTION);
  Mat4 m4 = quadToQuadMatrix4(map);
  m4[2][2] = 1.0f;
  kept.multMatrix(&m4[0][0]);
  kept.frustum(-0.1, 0.1, -0.1, 0.1, 0.1, 10.0);
  kept.matrixMode(GL_MODELVIEW);
  drawScene(kept);

  // The quad's pixels: those whose centre maps back into the quad (the map's
  // inverse), at least 0.02 NDC inside (a margin for the edges' rounding).
  const DMat3 back = quadToQuad(to, from);
  int inside = 0;
  std::uint32_t keptMin = ~0u, keptMax = 0;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const DVec2 ndc((x + 0.5) * 2.0 / kSide - 1.0, (y + 0.5) * 2.0 / kSide - 1.0);
      const DVec2 p = applyProjectiveMap(back, ndc);
      if (std::max(std::fabs(p.x), std::fabs(p.y)) > 0.25 - 0.02) continue;
      ++inside;
      EXPECT_EQ(stage.depthAt(x, y), quadDepth) << x << "," << y;
      EXPECT_EQ(stage.colorAt(x, y), (Rgba8{255, 255, 255, 255})) << x << "," << y;
      keptMin = std::min(keptMin, kept.depthAt(x, y));
      keptMax = std::max(keptMax, kept.depthAt(x, y));
    }
  EXPECT_GT(inside, 200);
  EXPECT_GT(keptMax - keptMin, 1000u);  // the 4x4 divides depth by the map's w
}

// Where the map's q reaches 0 (its horizon line) inside the view, the stage
// clips to |u| <= q, |v| <= q: nothing beyond the horizon is drawn, nothing
// wraps around, nothing is NaN. The map x' = x / (x + 0.5) sends the screen's
// right edge to 2/3: window x beyond 16 (1 + 2/3) = 26.7 stays empty; the
// line x = -1/4 goes to the left edge.
TEST(WindowMap, TheHorizonLineClips) {
  GLContext gl(kSide, kSide, indigoProfile());
  glm::mat3 m(0.0f);
  m[0] = glm::vec3(1.0f, 0.0f, 0.0f);  // u = x
  m[1] = glm::vec3(0.0f, 1.0f, 0.0f);  // v = y
  m[2] = glm::vec3(1.0f, 0.0f, 0.5f);  // q = x + 0.5
  gl.setWindowMap(m);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 3, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(-1.0f, -1.0f, 1.0f, 1.0f);
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const double xp = (x + 0.5) * 2.0 / kSide - 1.0, yp = (y + 0.5) * 2.0 / kSide - 1.0;
      // Back through the map: x = 0.5 x' / (1 - x'), y = y' (x + 0.5).
      const double xs = 0.5 * xp / (1.0 - xp), ys = yp * (xs + 0.5);
      const bool covered = xs <= 1.0 && std::fabs(ys) <= 1.0;
      const bool nearEdge = std::fabs(xs - 1.0) < 0.05 || std::fabs(std::fabs(ys) - 1.0) < 0.05;
      if (!nearEdge) {
        EXPECT_EQ(gl.stencilAt(x, y), covered ? 3u : 0u) << x << "," << y;
      }
    }
  EXPECT_EQ(gl.stencilAt(27, 16), 0u);
  EXPECT_EQ(gl.stencilAt(0, 16), 3u);
}

}  // namespace
}  // namespace mpr
