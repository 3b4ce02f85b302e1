// The draw stage driven from a snapshot filled by hand, with no GL call: a
// triangle's stencil and depth bytes, a culled one's, and the same bytes on
// row threads. The expected values are worked out here from the geometry.
#include <gtest/gtest.h>

#include <vector>

#include "framebuffer/profile.hpp"
#include "pipeline/draw/clipping.hpp"
#include "pipeline/draw/draw_snapshot.hpp"
#include "pipeline/draw/draw_stage.hpp"

namespace mpr {
namespace {

constexpr int kSize = 8;

// An 8x8 window, viewport the whole of it, depth range [0, 1]: normalised
// x, y in [-1, 1] land on [0, 8] (scale 4, translation 4), depth z on [0, 1].
// Stencil always passes; GL_INCR where the depth test (GL_LESS) passes,
// GL_INVERT where it fails. No colour is written.
DrawSnapshot stencilSnapshot() {
  DrawSnapshot s;
  s.frag.stencil.enabled = true;
  s.frag.stencil.func = CompareFunc::Always;
  s.frag.stencil.valueMask = s.frag.stencil.writeMask = 0xFF;
  s.frag.stencil.dpfail = StencilOp::Invert;
  s.frag.stencil.dppass = StencilOp::Incr;
  s.frag.depth.enabled = true;
  s.frag.depth.func = CompareFunc::Less;
  s.frag.colorMask = {false, false, false, false};
  s.pipeline = chooseFragmentPipeline(s.frag);
  s.window = {4.0f, 4.0f, 4.0f, 4.0f, 0.5f, 0.5f, kSize};
  s.drawRegion = s.scissoredFramebuffer = PixelRect{0, 0, kSize, kSize};
  s.clipPlanes = viewVolumePlanes();
  return s;
}

ClipVertex vertex(float x, float y, float z) { return {Vec4(x, y, z, 1.0f), {1, 1, 1, 1, 1, 1, 1, 1, 0}}; }

// The lower-left half of the window, wound counter-clockwise on the screen
// (a front face under glFrontFace(GL_CCW)): window corners (0, 0), (8, 0),
// (0, 8) at depth 0 (z = -1). A pixel's centre (x + 0.5, y + 0.5) is inside
// where x + y < 7, outside where x + y > 7 (the diagonal x + y == 7 runs
// through its centres: left to the fill rule, not asserted here).
const std::vector<ClipVertex> kLowerLeftCcw = {vertex(-1, -1, -1), vertex(1, -1, -1), vertex(-1, 1, -1)};
const std::vector<ClipVertex> kLowerLeftCw = {vertex(-1, -1, -1), vertex(-1, 1, -1), vertex(1, -1, -1)};

class DrawStageTest : public ::testing::TestWithParam<int> {  // the row threads
 protected:
  DrawStageTest() : stage(kSize, kSize, mesaProfile()) {
    stage.setThreads(GetParam());
    depthMax = mesaProfile().depthMax();
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) stage.framebuffer().depth(x, y) = depthMax;  // as glClear(GL_DEPTH_BUFFER_BIT)
  }
  // Each pixel off the diagonal: `inside` for those the triangle covers, `outside` for the others.
  void expectStencil(int inside, int outside) {
    stage.drain();
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (x + y == 7) continue;
        EXPECT_EQ(stage.framebuffer().stencil(x, y), x + y < 7 ? inside : outside) << x << ", " << y;
      }
  }

  DrawStage stage;
  std::uint32_t depthMax = 0;
};

TEST_P(DrawStageTest, ATriangleIncrementsTheStencilOfThePixelsItCoversAndStoresItsDepth) {
  const DrawSnapshot s = stencilSnapshot();
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCcw);
  expectStencil(1, 0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (x + y == 7) continue;
      EXPECT_EQ(stage.framebuffer().depth(x, y), x + y < 7 ? 0u : depthMax) << x << ", " << y;
    }
  // Drawn again at the same depth, GL_LESS fails: GL_INVERT makes 1 0xFE.
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCcw);
  expectStencil(0xFE, 0);
  // 28 pixels have x + y < 7, and the diagonal's 8 go to one side or the
  // other: each fragment tested once, written the first time only.
  const PipelineCounters& c = stage.counters();
  EXPECT_EQ(c.triangles, 2u);
  EXPECT_EQ(c.trianglesDrawn, 2u);
  EXPECT_EQ(c.fragmentsTested, 2 * c.fragmentsWritten);
  EXPECT_GE(c.fragmentsWritten, 28u);
  EXPECT_LE(c.fragmentsWritten, 36u);
}

TEST_P(DrawStageTest, ABackFaceIsCulledAndAFrontFaceDrawn) {
  DrawSnapshot s = stencilSnapshot();
  s.cullEnabled = true;
  s.cullFace = CullFace::Back;
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCw);  // clockwise: a back face
  expectStencil(0, 0);
  EXPECT_EQ(stage.counters().fragmentsTested, 0u);
  // Counted as llvmpipe counts it: assembled, and past clipping.
  EXPECT_EQ(stage.counters().triangles, 1u);
  EXPECT_EQ(stage.counters().trianglesDrawn, 1u);
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCcw);
  expectStencil(1, 0);
  // glFrontFace(GL_CW) makes the clockwise one the front face.
  s.frontFaceCcw = false;
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCcw);  // now a back face
  expectStencil(1, 0);
  s.cullFace = CullFace::FrontAndBack;
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCw);
  expectStencil(1, 0);
  s.cullFace = CullFace::Front;
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCcw);  // a back face again, drawn: depth fails, GL_INVERT
  expectStencil(0xFE, 0);
}

TEST_P(DrawStageTest, AnObserverSeesEachFragmentOfTheDraw) {
  DrawSnapshot s = stencilSnapshot();
  int fragments = 0, beyondTheDiagonal = 0;
  const FragmentObserver observer = [&](const FragmentEvent& e) {
    ++fragments;
    if (e.x + e.y > 7) ++beyondTheDiagonal;
    EXPECT_EQ(e.stencilAfter, e.stencilBefore + 1);
    EXPECT_EQ(e.depthIncoming, 0u);
  };
  s.observer = &observer;
  stage.draw(s, PrimitiveType::Triangles, kLowerLeftCcw);
  EXPECT_EQ(static_cast<std::uint64_t>(fragments), stage.counters().fragmentsTested);
  EXPECT_EQ(beyondTheDiagonal, 0);
  expectStencil(1, 0);
}

INSTANTIATE_TEST_SUITE_P(Threads, DrawStageTest, ::testing::Values(1, 2));

}  // namespace
}  // namespace mpr
