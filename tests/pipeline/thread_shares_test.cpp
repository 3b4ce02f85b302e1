// Row shares (DrawStage::setThreads, drawDeferred) with every draw shared
// out, however small (a share of 1 pixel): on every script of the
// conformance corpus, its reproducers and scenes/ (clipped polygons,
// llvmpipe fans, window maps, stencil, blending, accumulation), the
// colour, depth, stencil and accumulation buffers and the fragment counts
// at 2, 3 and 8 threads are those at 1, byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"

namespace mpr {
namespace {

struct Buffers {
  std::vector<Rgba8> color;
  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> stencil;
  std::vector<std::int16_t> accum;
  PipelineCounters counters;
};

Buffers runWithThreads(const Script& script, int threads) {
  const HardwareProfile profile = findProfile(script.profile.value_or("mesa")).value_or(mesaProfile());
  GLContext gl(script.width, script.height, profile);
  gl.setThreads(threads);
  runScript(script, gl);
  const Framebuffer& fb = gl.framebuffer();
  return {fb.colorData(), fb.depthData(), fb.stencilData(), fb.accumData(), gl.counters()};
}

void expectTheBytesOfOneThread(const Buffers& many, const Buffers& one, const std::string& where) {
  ASSERT_EQ(many.color, one.color) << where;
  ASSERT_EQ(many.depth, one.depth) << where;
  ASSERT_EQ(many.stencil, one.stencil) << where;
  ASSERT_EQ(many.accum, one.accum) << where;
  EXPECT_EQ(many.counters.triangles, one.counters.triangles) << where;
  EXPECT_EQ(many.counters.trianglesDrawn, one.counters.trianglesDrawn) << where;
  EXPECT_EQ(many.counters.fragmentsTested, one.counters.fragmentsTested) << where;
  EXPECT_EQ(many.counters.fragmentsWritten, one.counters.fragmentsWritten) << where;
}

TEST(ThreadShares, EveryDrawSharedGivesTheBytesAndCountsOfOneThread) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  int scripts = 0;
  for (const char* folder : {"tests/conformance", "tests/conformance/repro", "scenes"})
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      if (entry.path().extension() != ".gls") continue;
      const std::string path = entry.path().string();
      const Script script = parseScript(readScriptText(path), path);
      const Buffers one = runWithThreads(script, 1);
      for (int threads : {2, 3, 8}) {
        expectTheBytesOfOneThread(runWithThreads(script, threads), one,
                                  path + " at " + std::to_string(threads) + " threads");
      }
      ++scripts;
    }
  EXPECT_GT(scripts, 50);
}

// One draw far longer than the piece queued at a time
// (GLContext::kTrianglesPerQueuedDraw): overlapping triangles, a third of
// them crossing the view volume (llvmpipe's fans), counted in the stencil
// and depth tested, so every pixel's value depends on its fragments' order.
TEST(ThreadShares, ADrawQueuedInPiecesGivesTheBytesAndCountsOfOneThread) {
  std::mt19937 random(14);
  std::uniform_real_distribution<float> inside(-0.9f, 0.9f), across(-1.6f, 1.6f), depth(-0.9f, 0.9f);
  std::string text =
      "@framebuffer 48 40\n@profile mesa\nglClear GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT\nglEnable GL_DEPTH_TEST\nglEnable GL_STENCIL_TEST\n"
      "glStencilFunc GL_ALWAYS 0 255\nglStencilOp GL_INCR GL_INVERT GL_INCR\nglShadeModel GL_SMOOTH\n"
      "glBegin GL_TRIANGLES\n";
  const int triangles = 7 * static_cast<int>(GLContext::kTrianglesPerQueuedDraw) / 2;
  for (int t = 0; t < triangles; ++t)
    for (int v = 0; v < 3; ++v) {
      auto& xy = t % 3 == 0 ? across : inside;
      text += "glColor3f " + std::to_string(t % 7 / 7.0) + " " + std::to_string(v / 3.0) + " 0.5\n";
      text += "glVertex3f " + std::to_string(xy(random)) + " " + std::to_string(xy(random)) + " " +
              std::to_string(depth(random)) + "\n";
    }
  text += "glEnd\n";
  const Script script = parseScript(text, "long_draw.gls");
  const Buffers one = runWithThreads(script, 1);
  EXPECT_EQ(one.counters.triangles, static_cast<std::uint64_t>(triangles));
  EXPECT_GT(one.counters.fragmentsWritten, 0u);
  for (int threads : {2, 3, 8})
    expectTheBytesOfOneThread(runWithThreads(script, threads), one, "at " + std::to_string(threads) + " threads");
}

}  // namespace
}  // namespace mpr
