// Row shares (GLContext::setThreads, drawDeferred) with every draw shared
// out, however small (a share of 1 pixel): on every script of the
// conformance corpus, its reproducers and scenes/ (clipped polygons,
// llvmpipe fans, window maps, stencil, blending, accumulation), the
// colour, depth, stencil and accumulation buffers and the fragment counts
// at 2, 3 and 8 threads are those at 1, byte for byte.
#include <gtest/gtest.h>

#include <filesystem>

#include "framebuffer/profile.hpp"
#include "pipeline/gl_context.hpp"
#include "pipeline/gl_script.hpp"
#include "pipeline/gl_script_runner.hpp"

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
        const Buffers many = runWithThreads(script, threads);
        const std::string where = path + " at " + std::to_string(threads) + " threads";
        ASSERT_EQ(many.color, one.color) << where;
        ASSERT_EQ(many.depth, one.depth) << where;
        ASSERT_EQ(many.stencil, one.stencil) << where;
        ASSERT_EQ(many.accum, one.accum) << where;
        EXPECT_EQ(many.counters.triangles, one.counters.triangles) << where;
        EXPECT_EQ(many.counters.trianglesDrawn, one.counters.trianglesDrawn) << where;
        EXPECT_EQ(many.counters.fragmentsTested, one.counters.fragmentsTested) << where;
        EXPECT_EQ(many.counters.fragmentsWritten, one.counters.fragmentsWritten) << where;
      }
      ++scripts;
    }
  EXPECT_GT(scripts, 50);
}

}  // namespace
}  // namespace mpr
