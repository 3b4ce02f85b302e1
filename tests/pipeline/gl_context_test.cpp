// The GL state machine end to end: per-pixel results of GL calls.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pipeline/gl/gl_context.hpp"

namespace mpr {
namespace {

// A context whose object coordinates are window coordinates.
GLContext windowContext(int w = 16, int h = 16, const HardwareProfile& p = indigoProfile()) {
  GLContext gl(w, h, p);
  gl.matrixMode(GL_PROJECTION);
  gl.ortho(0, w, 0, h, -1, 1);
  gl.matrixMode(GL_MODELVIEW);
  return gl;
}

int countStencil(const GLContext& gl, std::uint32_t value) {
  int n = 0;
  for (int y = 0; y < gl.framebuffer().height(); ++y)
    for (int x = 0; x < gl.framebuffer().width(); ++x) n += gl.stencilAt(x, y) == value;
  return n;
}

TEST(GLContext, StencilReplaceThroughARectangle) {
  GLContext gl = windowContext();
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 129, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(2, 3, 6, 5);  // pixels x 2..5, y 3..4
  EXPECT_EQ(gl.stencilAt(3, 4), 129u);
  EXPECT_EQ(gl.stencilAt(2, 3), 129u);
  EXPECT_EQ(gl.stencilAt(6, 4), 0u);
  EXPECT_EQ(gl.stencilAt(3, 5), 0u);
  EXPECT_EQ(countStencil(gl, 129), 8);
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
}

TEST(GLContext, StencilRefIsClampedToTheStencilRange) {
  GLContext gl = windowContext();
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 1000, 0xFF);  // clamped to 255
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(0, 0, 1, 1);
  EXPECT_EQ(gl.stencilAt(0, 0), 255u);
  gl.stencilFunc(GL_ALWAYS, -5, 0xFF);  // clamped to 0
  gl.rectf(0, 0, 1, 1);
  EXPECT_EQ(gl.stencilAt(0, 0), 0u);
}

TEST(GLContext, ClearHonoursScissorAndStencilWriteMask) {
  GLContext gl = windowContext(8, 8);
  gl.clearStencil(0xFF);
  gl.clear(GL_STENCIL_BUFFER_BIT);
  gl.enable(GL_SCISSOR_TEST);
  gl.scissor(2, 2, 3, 2);
  gl.stencilMask(0x0F);
  gl.clearStencil(0x00);
  gl.clear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(gl.stencilAt(2, 2), 0xF0u);
  EXPECT_EQ(gl.stencilAt(4, 3), 0xF0u);
  EXPECT_EQ(gl.stencilAt(5, 3), 0xFFu);
  EXPECT_EQ(gl.stencilAt(2, 4), 0xFFu);
  EXPECT_EQ(countStencil(gl, 0xF0), 6);
}

TEST(GLContext, DepthRangeMapsNdcDepth) {
  GLContext gl = windowContext(4, 4);
  gl.enable(GL_DEPTH_TEST);
  gl.depthFunc(GL_ALWAYS);
  gl.depthRange(0.25, 0.75);
  gl.rectf(0, 0, 4, 4);  // z_ndc = 0 under glOrtho(-1, 1): window depth 0.5
  // 0.5 * (2^24 - 1) = 8388607.5, rounded to nearest even: 8388608.
  EXPECT_EQ(gl.depthAt(1, 1), 8388608u);
  gl.depthRange(1.0, 0.0);  // reversed range
  gl.begin(GL_QUADS);
  gl.vertex4f(0, 0, 0.5f, 1);  // glOrtho(-1, 1) maps z = 0.5 to z_ndc = -0.5
  gl.vertex4f(4, 0, 0.5f, 1);
  gl.vertex4f(4, 4, 0.5f, 1);
  gl.vertex4f(0, 4, 0.5f, 1);
  gl.end();
  // z_w = -0.5 * (0 - 1) / 2 + 0.5 = 0.75; 0.75 * 16777215 = 12582911.25 -> 12582911.
  EXPECT_EQ(gl.depthAt(2, 2), 12582911u);
}

TEST(GLContext, DepthTestDisabledWritesNoDepth) {
  GLContext gl = windowContext(4, 4);
  gl.clearDepth(1.0);
  gl.clear(GL_DEPTH_BUFFER_BIT);
  gl.rectf(0, 0, 4, 4);
  EXPECT_EQ(gl.depthAt(0, 0), 0xFFFFFFu);
}

TEST(GLContext, UserClipPlaneInObjectCoordinates) {
  GLContext gl = windowContext(16, 4);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  // Keep x >= 10 (object coordinates), i.e. pixels 10..15.
  const double eq[4] = {1, 0, 0, -10};
  gl.clipPlane(GL_CLIP_PLANE0, eq);
  gl.enable(GL_CLIP_PLANE0);
  gl.rectf(0, 0, 16, 4);
  for (int x = 0; x < 16; ++x) EXPECT_EQ(gl.stencilAt(x, 1), x >= 10 ? 1u : 0u) << x;
}

TEST(GLContext, ClipPlaneIsFixedInEyeSpaceWhenSpecified) {
  GLContext gl = windowContext(16, 4);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.pushMatrix();
  gl.translate(4, 0, 0);
  const double eq[4] = {1, 0, 0, -2};  // x_object >= 2, i.e. x_eye >= 6
  gl.clipPlane(GL_CLIP_PLANE0, eq);
  gl.popMatrix();  // changing the modelview afterwards does not move the plane
  gl.enable(GL_CLIP_PLANE0);
  gl.rectf(0, 0, 16, 4);
  for (int x = 0; x < 16; ++x) EXPECT_EQ(gl.stencilAt(x, 0), x >= 6 ? 1u : 0u) << x;
}

TEST(GLContext, NearAndFarPlanesClip) {
  GLContext gl = windowContext(8, 2);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  // glOrtho(.., -1, 1): eye z in [-1, 1] is visible (z_object = -z_ndc).
  gl.begin(GL_QUADS);  // beyond the far plane: dropped
  gl.vertex4f(0, 0, -1.5f, 1);
  gl.vertex4f(8, 0, -1.5f, 1);
  gl.vertex4f(8, 2, -1.5f, 1);
  gl.vertex4f(0, 2, -1.5f, 1);
  gl.end();
  EXPECT_EQ(countStencil(gl, 1), 0);
  // z goes from -3 at x = 0 to 1 at x = 8: visible for z >= -1, x >= 4.
  gl.begin(GL_QUADS);
  gl.vertex4f(0, 0, -3, 1);
  gl.vertex4f(8, 0, 1, 1);
  gl.vertex4f(8, 2, 1, 1);
  gl.vertex4f(0, 2, -3, 1);
  gl.end();
  for (int x = 0; x < 8; ++x) EXPECT_EQ(gl.stencilAt(x, 0), x >= 4 ? 1u : 0u) << x;
}

TEST(GLContext, NonFiniteVertexDropsOnlyItsPrimitive) {
  GLContext gl = windowContext(8, 8);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 7, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  gl.begin(GL_TRIANGLES);
  gl.vertex4f(0, 0, 0, 1);  // a NaN triangle
  gl.vertex4f(nan, 4, 0, 1);
  gl.vertex4f(4, 4, 0, 1);
  gl.vertex4f(0, 0, 0, 1);  // an infinite one
  gl.vertex4f(8, 0, inf, 1);
  gl.vertex4f(8, 8, 0, 1);
  gl.vertex4f(4, 0, 0, 1);  // and a good one: pixels strictly right of x = 4 below the diagonal
  gl.vertex4f(8, 0, 0, 1);
  gl.vertex4f(8, 4, 0, 1);
  gl.end();
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
  // Only the good triangle wrote: (4,0)-(8,0)-(8,4) covers 4+3+2+1 = 10 pixels
  // (centres on its left-leaning hypotenuse belong to it, bottom edge y=0 has no centres).
  EXPECT_EQ(countStencil(gl, 7), 10);
  EXPECT_EQ(gl.stencilAt(7, 0), 7u);
  EXPECT_EQ(gl.stencilAt(1, 1), 0u);
}

TEST(GLContext, VertexWithWNearZeroIsClippedNotExploded) {
  GLContext gl(8, 8, indigoProfile());  // identity matrices: clip = object coordinates
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (float w : {1e-30f, -1e-30f, 0.0f, 1e-7f}) {
    gl.begin(GL_TRIANGLES);
    gl.vertex4f(-1, -1, 0, 1);
    gl.vertex4f(1, -1, 0, 1);
    gl.vertex4f(0, 1, 0, w);
    gl.end();
    EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
  }
  // Every pixel holds 0 or 1, nothing else was touched.
  EXPECT_EQ(countStencil(gl, 0) + countStencil(gl, 1), 64);
}

TEST(GLContext, HugeAndTinyCoordinates) {
  GLContext gl = windowContext(8, 8);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 3, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.begin(GL_TRIANGLES);  // covers the whole window
  gl.vertex4f(-1e6f, -1e6f, 0, 1);
  gl.vertex4f(1e6f, -1e6f, 0, 1);
  gl.vertex4f(0, 1e6f, 0, 1);
  gl.end();
  EXPECT_EQ(countStencil(gl, 3), 64);
  gl.stencilFunc(GL_ALWAYS, 4, 0xFF);
  gl.begin(GL_TRIANGLES);  // far smaller than a sub-pixel step: covers nothing
  gl.vertex4f(3.5f, 3.5f, 0, 1);
  gl.vertex4f(3.5f + 1e-6f, 3.5f, 0, 1);
  gl.vertex4f(3.5f, 3.5f + 1e-6f, 0, 1);
  gl.end();
  EXPECT_EQ(countStencil(gl, 4), 0);
}

TEST(GLContext, CullingFollowsFrontFace) {
  GLContext gl = windowContext(4, 4);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 1, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  gl.enable(GL_CULL_FACE);  // cull back faces; CCW is front
  gl.rectf(0, 0, 4, 4);     // counter-clockwise: drawn
  gl.rectf(4, 0, 0, 4);     // clockwise: culled
  EXPECT_EQ(gl.stencilAt(1, 1), 1u);
  gl.frontFace(GL_CW);
  gl.rectf(4, 0, 0, 4);  // now front
  EXPECT_EQ(gl.stencilAt(1, 1), 2u);
  gl.cullFace(GL_FRONT_AND_BACK);
  gl.rectf(0, 0, 4, 4);
  gl.rectf(4, 0, 0, 4);
  EXPECT_EQ(gl.stencilAt(1, 1), 2u);
}

TEST(GLContext, FlatShadingUsesTheProvokingVertex) {
  GLContext gl = windowContext(8, 8);
  gl.shadeModel(GL_FLAT);
  gl.begin(GL_TRIANGLES);  // last vertex provokes
  gl.color4f(1, 0, 0, 1);
  gl.vertex4f(0, 0, 0, 1);
  gl.color4f(0, 1, 0, 1);
  gl.vertex4f(8, 0, 0, 1);
  gl.color4f(0, 0, 1, 1);
  gl.vertex4f(0, 8, 0, 1);
  gl.end();
  EXPECT_EQ(gl.colorAt(1, 1), (Rgba8{0, 0, 255, 255}));
  gl.begin(GL_POLYGON);  // first vertex provokes
  gl.color4f(1, 0, 0, 1);
  gl.vertex4f(0, 0, 0, 1);
  gl.color4f(0, 1, 0, 1);
  gl.vertex4f(8, 0, 0, 1);
  gl.color4f(0, 0, 1, 1);
  gl.vertex4f(8, 8, 0, 1);
  gl.end();
  EXPECT_EQ(gl.colorAt(6, 1), (Rgba8{255, 0, 0, 255}));
}

TEST(GLContext, SmoothColourInterpolatesAtPixelCentres) {
  GLContext gl = windowContext(4, 1);
  gl.begin(GL_QUADS);
  gl.color4f(0, 0, 0, 1);
  gl.vertex4f(0, 0, 0, 1);
  gl.color4f(1, 0, 0, 1);
  gl.vertex4f(4, 0, 0, 1);
  gl.vertex4f(4, 1, 0, 1);
  gl.color4f(0, 0, 0, 1);
  gl.vertex4f(0, 1, 0, 1);
  gl.end();
  // Red = x / 4 at centres 0.5, 1.5, 2.5, 3.5: 0.125 0.375 0.625 0.875, times
  // 255 = 31.875 95.625 159.375 223.125, rounded: 32 96 159 223.
  EXPECT_EQ(gl.colorAt(0, 0)[0], 32);
  EXPECT_EQ(gl.colorAt(1, 0)[0], 96);
  EXPECT_EQ(gl.colorAt(2, 0)[0], 159);
  EXPECT_EQ(gl.colorAt(3, 0)[0], 223);
}

TEST(GLContext, LinearFogAtAChosenDepth) {
  GLContext gl(4, 4, indigoProfile());
  gl.matrixMode(GL_PROJECTION);
  gl.ortho(0, 4, 0, 4, 0, 20);
  gl.matrixMode(GL_MODELVIEW);
  gl.enable(GL_FOG);
  gl.fogi(GL_FOG_MODE, GL_LINEAR);
  gl.fogf(GL_FOG_START, 0);
  gl.fogf(GL_FOG_END, 10);
  const float black[4] = {0, 0, 0, 1};
  gl.fogfv(GL_FOG_COLOR, black, 4);
  gl.color4f(1, 1, 1, 1);
  for (GLenumValue hint : {GL_NICEST, GL_FASTEST}) {
    gl.hint(GL_FOG_HINT, hint);
    gl.begin(GL_QUADS);  // eye z = -5: fog coordinate 5, f = (10 - 5) / 10 = 0.5
    gl.vertex4f(0, 0, -5, 1);
    gl.vertex4f(4, 0, -5, 1);
    gl.vertex4f(4, 4, -5, 1);
    gl.vertex4f(0, 4, -5, 1);
    gl.end();
    // 0.5 * 255 = 127.5, rounded to nearest even: 128. Alpha is not fogged.
    EXPECT_EQ(gl.colorAt(2, 2), (Rgba8{128, 128, 128, 255})) << hint;
  }
}

TEST(GLContext, GLErrorsAreRecordedAndTheCallIgnored) {
  GLContext gl = windowContext(4, 4);
  gl.end();
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_INVALID_OPERATION));
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
  gl.popMatrix();
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_STACK_UNDERFLOW));
  gl.stencilFunc(GL_KEEP, 1, 0xFF);
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_INVALID_ENUM));
  EXPECT_EQ(gl.fragmentState().stencil.func, CompareFunc::Always);
  gl.begin(GL_TRIANGLES);
  gl.enable(GL_STENCIL_TEST);  // not allowed between glBegin and glEnd
  gl.end();
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_INVALID_OPERATION));
  EXPECT_FALSE(gl.isEnabled(GL_STENCIL_TEST));
  // Only the first error is kept until read.
  gl.viewport(0, 0, -1, 4);
  gl.enable(GL_KEEP);
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_INVALID_VALUE));
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
  for (int i = 0; i < 31; ++i) gl.pushMatrix();
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_NO_ERROR));
  gl.pushMatrix();  // the 33rd entry
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_STACK_OVERFLOW));
}

TEST(GLContext, AccumulationThroughTheGLCalls) {
  GLContext gl = windowContext(2, 2, mesaProfile());
  gl.clearColor(1, 1, 1, 1);
  gl.clear(GL_COLOR_BUFFER_BIT);
  gl.accum(GL_LOAD, 0.5f);  // 255 * (1/255) * (0.5 * 32767) = 16383.5 -> 16383
  EXPECT_EQ(gl.accumAt(0, 0), (std::array<std::int16_t, 4>{16383, 16383, 16383, 16383}));
  gl.accum(GL_ACCUM, 0.5f);
  EXPECT_EQ(gl.accumAt(1, 1)[0], 32766);
  gl.accum(GL_RETURN, 1.0f);  // 32766 / 32767 * 255 = 254.99 -> 255
  EXPECT_EQ(gl.colorAt(0, 0), (Rgba8{255, 255, 255, 255}));
  gl.accum(GL_KEEP, 1.0f);
  EXPECT_EQ(gl.getError(), static_cast<GLenumValue>(GL_INVALID_ENUM));
}

TEST(GLContext, FragmentObserverSeesEveryFragmentOfADraw) {
  GLContext gl = windowContext(4, 4);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 0, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  int events = 0;
  gl.fragmentObserver = [&](const FragmentEvent& e) {
    if (e.x == 1 && e.y == 1) {
      EXPECT_EQ(e.stencilAfter, e.stencilBefore + 1);
      ++events;
    }
  };
  gl.begin(GL_QUADS);  // two overlapping quads in one draw
  for (int k = 0; k < 2; ++k) {
    gl.vertex4f(0, 0, 0, 1);
    gl.vertex4f(4, 0, 0, 1);
    gl.vertex4f(4, 4, 0, 1);
    gl.vertex4f(0, 4, 0, 1);
  }
  gl.end();
  // A GL_QUADS draw stays open for the next GL_QUADS block until a state
  // change or a reader closes it, as Mesa's vbo keeps it (gl_context.hpp).
  gl.flushVertices();
  EXPECT_EQ(events, 2);
  EXPECT_EQ(gl.stencilAt(1, 1), 2u);
}

}  // namespace
}  // namespace mpr
