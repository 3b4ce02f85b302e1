// Where GL 1.1 is exact and MPR disagreed with llvmpipe (issue 17, classes
// 1-4), and where GL leaves the result open and MPR now takes llvmpipe's
// choice (class 6). The reproducers themselves run against Mesa in CTest
// (tests/conformance/repro/); these pin the values by hand.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include "raster/fog.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "pipeline/draw/lighting.hpp"

namespace mpr {
namespace {

bool sameColour(Rgba8 a, Rgba8 b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3]; }

// Class 1: glMaterial between glBegin and glEnd applies to the vertices after
// it (GL 1.1 section 2.6.3). Emission only (ambient 0), so the colour is the
// emission: the first triangle red, the second green.
TEST(LlvmpipeAgreement, MaterialInsideBeginAppliesToTheVerticesAfterIt) {
  GLContext gl(16, 16, mesaProfile());
  gl.enable(GL_LIGHTING);
  const float black[4] = {0, 0, 0, 1}, red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1};
  gl.lightModelfv(GL_LIGHT_MODEL_AMBIENT, black, 4);
  gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, red, 4);
  gl.begin(GL_TRIANGLES);
  gl.vertex4f(-1, -1, 0, 1);  // lower-left half: red
  gl.vertex4f(1, -1, 0, 1);
  gl.vertex4f(-1, 1, 0, 1);
  gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, green, 4);
  gl.vertex4f(1, -1, 0, 1);  // upper-right half: green
  gl.vertex4f(1, 1, 0, 1);
  gl.vertex4f(-1, 1, 0, 1);
  gl.end();
  EXPECT_TRUE(sameColour(gl.colorAt(2, 2), Rgba8{255, 0, 0, 255}));
  EXPECT_TRUE(sameColour(gl.colorAt(13, 13), Rgba8{0, 255, 0, 255}));
  // After glEnd the material in force is the last one set.
  gl.rectf(-1, -1, 1, 1);
  EXPECT_TRUE(sameColour(gl.colorAt(2, 2), Rgba8{0, 255, 0, 255}));
}

// Class 2: a clipped GL_QUADS quad is split (0,1,3)(1,2,3) for coverage and
// colour. A flat square whose corner colours are not affine (red, black,
// red, black): split (0,1,2)(0,2,3) the diagonal 0-2 is red, split
// (0,1,3)(1,2,3) the diagonal 1-3 is black. To make the draw module clip,
// vertex 0 is put just beyond z = -1 (only a sliver at its corner is lost).
TEST(LlvmpipeAgreement, AClippedQuadIsCoveredAndColouredByTheOtherDiagonal) {
  auto centre = [](bool clip) {
    GLContext gl(16, 16, mesaProfile());
    gl.begin(GL_QUADS);
    gl.color4f(1, 0, 0, 1);
    gl.vertex4f(-1, -1, clip ? -1.0001f : 0.0f, 1);
    gl.color4f(0, 0, 0, 1);
    gl.vertex4f(1, -1, 0, 1);
    gl.color4f(1, 0, 0, 1);
    gl.vertex4f(1, 1, 0, 1);
    gl.color4f(0, 0, 0, 1);
    gl.vertex4f(-1, 1, 0, 1);
    gl.end();
    return gl.colorAt(8, 8)[0];  // on both diagonals' crossing: the pixel centre (8.5, 8.5) is near it
  };
  // Pixel (8,8)'s centre is 0.5 right of and 0.5 above the crossing: on the
  // (0,1,2) side of 0-2, and on the (1,2,3) side of 1-3.
  EXPECT_GT(centre(false), 128);  // 0-2 red through the middle
  EXPECT_LT(centre(true), 128);   // 1-3 black through the middle
}

// Class 2: consecutive GL_QUADS blocks with only attributes between them are
// one draw in Mesa; when a later block clips, the earlier ones take the
// other diagonal too. With a state change between them they do not.
TEST(LlvmpipeAgreement, ConsecutiveQuadBlocksShareTheSplitOfTheirDraw) {
  auto first = [](bool stateChangeBetween) {
    GLContext gl(16, 16, mesaProfile());
    gl.begin(GL_QUADS);  // unclipped, corner colours not affine
    gl.color4f(1, 0, 0, 1);
    gl.vertex4f(-1, -1, 0, 1);
    gl.color4f(0, 0, 0, 1);
    gl.vertex4f(1, -1, 0, 1);
    gl.color4f(1, 0, 0, 1);
    gl.vertex4f(1, 1, 0, 1);
    gl.color4f(0, 0, 0, 1);
    gl.vertex4f(-1, 1, 0, 1);
    gl.end();
    if (stateChangeBetween) gl.flush();
    return gl.colorAt(8, 8)[0];
  };
  auto withClippedSecond = [](bool stateChangeBetween) {
    GLContext gl(16, 16, mesaProfile());
    gl.begin(GL_QUADS);
    gl.color4f(1, 0, 0, 1);
    gl.vertex4f(-1, -1, 0, 1);
    gl.color4f(0, 0, 0, 1);
    gl.vertex4f(1, -1, 0, 1);
    gl.color4f(1, 0, 0, 1);
    gl.vertex4f(1, 1, 0, 1);
    gl.color4f(0, 0, 0, 1);
    gl.vertex4f(-1, 1, 0, 1);
    gl.end();
    if (stateChangeBetween) gl.flush();
    gl.begin(GL_QUADS);  // entirely beyond x = 1: clipped away, draws nothing
    gl.vertex4f(2, -1, 0, 1);
    gl.vertex4f(3, -1, 0, 1);
    gl.vertex4f(3, 1, 0, 1);
    gl.vertex4f(2, 1, 0, 1);
    gl.end();
    return gl.colorAt(8, 8)[0];
  };
  EXPECT_EQ(withClippedSecond(true), first(true));    // separate draws: (0,1,2)(0,2,3)
  EXPECT_GT(withClippedSecond(true), 128);
  EXPECT_LT(withClippedSecond(false), 128);           // one draw that clips: (0,1,3)(1,2,3)
}

// Class 3: Mesa keeps glDepthRange in single precision.
TEST(LlvmpipeAgreement, DepthRangeIsKeptInSinglePrecision) {
  GLContext gl(4, 4, mesaProfile());
  gl.depthRange(0.9914006740828817, 0.994552);
  EXPECT_EQ(gl.depthRangeValues()[0], static_cast<double>(0.9914006740828817f));
  EXPECT_EQ(gl.depthRangeValues()[1], static_cast<double>(0.994552f));
}

// Class 6: 0^0 in the specular term is 1, as llvmpipe takes it. Light from
// below the surface's tangent plane towards the viewer: N.L = 0.0995 > 0,
// N.H < 0; diffuse and ambient black, specular white.
TEST(LlvmpipeAgreement, ShininessZeroWithNDotHNegativeGivesFullSpecular) {
  LightingState s;
  s.model.ambient = Vec4(0, 0, 0, 1);
  s.lights[0].enabled = true;
  s.lights[0].specular = Vec4(1, 1, 1, 1);
  s.lights[0].position = Vec4(0, -1, -0.1f, 0);
  s.material[0].specular = Vec4(1, 1, 1, 1);
  s.material[0].shininess = 0.0f;
  const Vec4 c = lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, -1), false);
  EXPECT_EQ(c, Vec4(1, 1, 1, 1));
}

// Class 6: a specular term 0 x infinity (an unnormalised normal of length 3
// to the power 128, material specular 0) is dropped, not NaN: the diffuse
// term 3 x 0.8 clamps to 1.
TEST(LlvmpipeAgreement, AnOverflowedSpecularTermIsDroppedAndTheColourClamped) {
  LightingState s;
  s.lights[0].enabled = true;
  s.lights[0].diffuse = s.lights[0].specular = Vec4(1, 1, 1, 1);
  s.material[0].shininess = 128.0f;
  const Vec4 c = lightVertex(s, Vec4(0, 0, 0, 1), Vec3(0, 0, 3), false);
  EXPECT_EQ(c, Vec4(1, 1, 1, 1));
}

// Class 6: linear fog with start = end is f = clamp(c - end), Mesa's
// multiply-add with its constants (1, -end).
TEST(LlvmpipeAgreement, LinearFogWithStartEqualToEnd) {
  FogState fog;
  fog.mode = FogMode::Linear;
  fog.start = fog.end = 2.0f;
  EXPECT_EQ(fogFactor(fog, 1.5f), 0.0f);
  EXPECT_EQ(fogFactor(fog, 2.25f), 0.25f);
  EXPECT_EQ(fogFactor(fog, 9.0f), 1.0f);
}

// Class 5 is not followed: glColor3 sets alpha 1 (GL 1.1 section 2.7), and
// only a context told to emulate Mesa's departure keeps the old alpha.
TEST(LlvmpipeAgreement, Color3SetsAlphaOneUnlessMesasDepartureIsEmulated) {
  for (const bool emulate : {false, true}) {
    GLContext gl(4, 4, mesaProfile());
    if (emulate) gl.emulateMesaDepartures(kColor3KeepsAlpha);
    gl.color4f(1, 1, 1, 0.2f);
    gl.color3f(0, 1, 0);
    gl.rectf(-1, -1, 1, 1);
    EXPECT_EQ(gl.colorAt(1, 1)[3], emulate ? 51 : 255);
  }
}

}  // namespace
}  // namespace mpr
