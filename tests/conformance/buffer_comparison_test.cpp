// The conformance bounds: which scripts count as exactly representable, and
// the verdict on synthetic buffers at and just past each bound.
#include <gtest/gtest.h>

#include "conformance/buffer_comparison.hpp"

namespace mpr {
namespace {

BufferSet uniformSet(int w, int h, std::uint8_t c, std::uint32_t z, std::uint8_t s) {
  BufferSet b;
  b.point = "final";
  b.width = w;
  b.height = h;
  b.color.assign(static_cast<std::size_t>(w) * h * 4, c);
  b.depth.assign(static_cast<std::size_t>(w) * h, z);
  b.stencil.assign(static_cast<std::size_t>(w) * h, s);
  return b;
}

TEST(ConformanceBounds, ExactCoordinatesNeedDyadicOrtho) {
  EXPECT_TRUE(boundsFor(parseScript("glOrtho 0 64 0 64 -1 1\nglVertex2f 1.25 3.5\n", "a")).exactCoordinates);
  EXPECT_FALSE(boundsFor(parseScript("glVertex2f 0.1 3\n", "b")).exactCoordinates);        // 0.1 is not k/256
  EXPECT_FALSE(boundsFor(parseScript("gluPerspective 45 1 1 10\n", "c")).exactCoordinates);
  EXPECT_FALSE(boundsFor(parseScript("glRotatef 30 0 0 1\n", "d")).exactCoordinates);
  EXPECT_FALSE(boundsFor(parseScript("glVertex4f 1 1 0 2\n", "e")).exactCoordinates);
  EXPECT_TRUE(boundsFor(parseScript("glEnable GL_LIGHTING\n", "g")).litOrFogged);
  EXPECT_EQ(boundsFor(parseScript("glEnable GL_FOG\n", "h")).colorBound(), 2);
  EXPECT_EQ(boundsFor(parseScript("glEnable GL_BLEND\n", "i")).colorBound(), 1);
}

TEST(ConformanceBounds, VerdictAtEachBound) {
  const ConformanceBounds exact{true, false}, inexact{false, false};
  BufferSet mpr = uniformSet(100, 10, 50, 1000, 7), mesa = mpr;
  EXPECT_TRUE(compareBuffers(mpr, mesa, exact).conforms());
  mesa.color[0] = 51;  // colour off by 1: within
  mesa.depth[5] = 1001;  // depth off by 1: within
  PointAgreement p = compareBuffers(mpr, mesa, exact);
  EXPECT_TRUE(p.conforms());
  EXPECT_EQ(p.color.agree, 999u);
  EXPECT_EQ(p.depth.maxDiff, 1);
  mesa.color[4] = 52;  // off by 2: out for unlit colour
  EXPECT_FALSE(compareBuffers(mpr, mesa, exact).color.conforms());
  EXPECT_TRUE(compareBuffers(mpr, mesa, ConformanceBounds{true, true}).color.conforms());
  mesa.depth[9] = 998;
  EXPECT_FALSE(compareBuffers(mpr, mesa, exact).depth.conforms());
  // Stencil: one pixel in 1000 differs. Exact scripts allow none, others 0.1 %.
  BufferSet s1 = uniformSet(100, 10, 0, 0, 7), s2 = s1;
  s2.stencil[3] = 8;
  EXPECT_FALSE(compareBuffers(s1, s2, exact).stencil.conforms());
  EXPECT_TRUE(compareBuffers(s1, s2, inexact).stencil.conforms());
  s2.stencil[4] = 8;  // two in 1000: past 99.9 %
  EXPECT_FALSE(compareBuffers(s1, s2, inexact).stencil.conforms());
  const PointAgreement q = compareBuffers(s1, s2, inexact);
  ASSERT_EQ(q.stencil.first.size(), 2u);
  EXPECT_EQ(q.stencil.first[0].x, 3);
  EXPECT_EQ(q.stencil.first[0].mpr[0], 7);
  EXPECT_EQ(q.stencil.first[0].mesa[0], 8);
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

TEST(ColourMaterialBackInBegin, RecognisedByItsCalls) {
  const char* twoSide = "glLightModeli GL_LIGHT_MODEL_TWO_SIDE 1\n";
  // Colour material on the back with a colour inside glBegin.
  EXPECT_TRUE(showsColourMaterialBackInBegin(parseScript(
      std::string(twoSide) + "glColorMaterial GL_BACK GL_DIFFUSE\nglBegin GL_TRIANGLES\nglColor3f 1 0 0\nglEnd\n", "a")));
  // A glMaterial of the back (or both faces) inside glBegin.
  EXPECT_TRUE(showsColourMaterialBackInBegin(parseScript(
      std::string(twoSide) + "glBegin GL_TRIANGLES\nglMaterialfv GL_BACK GL_AMBIENT 1 0 0 1\nglEnd\n", "b")));
  EXPECT_TRUE(showsColourMaterialBackInBegin(parseScript(
      std::string(twoSide) + "glBegin GL_TRIANGLES\nglMaterialf GL_FRONT_AND_BACK GL_SHININESS 5\nglEnd\n", "c")));
  // Not: the front only, outside glBegin, or one-sided lighting.
  EXPECT_FALSE(showsColourMaterialBackInBegin(parseScript(
      std::string(twoSide) + "glBegin GL_TRIANGLES\nglMaterialfv GL_FRONT GL_AMBIENT 1 0 0 1\nglEnd\n", "d")));
  EXPECT_FALSE(showsColourMaterialBackInBegin(parseScript(
      std::string(twoSide) + "glMaterialfv GL_BACK GL_AMBIENT 1 0 0 1\nglBegin GL_TRIANGLES\nglEnd\n", "e")));
  EXPECT_FALSE(showsColourMaterialBackInBegin(
      parseScript("glBegin GL_TRIANGLES\nglMaterialfv GL_BACK GL_AMBIENT 1 0 0 1\nglEnd\n", "f")));
}

}  // namespace
}  // namespace mpr
