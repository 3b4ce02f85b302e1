// `mpr gl` (and `mpr test`, `mpr step`) run a script through ScriptExecutor;
// `mpr conform` replays it on MPR with the context alone (replayOnMpr).
// What mpr conform holds to Mesa's bounds must be what mpr gl writes: on
// every script of the corpus and its reproducers, both give the same
// colour, depth and stencil bytes at every @snapshot and at the end. (The
// runner once flushed Mesa's open GL_QUADS draw before every state call,
// the replay only where the context does: quads_merged_blocks.gls agreed
// with llvmpipe in mpr conform and not in mpr gl.)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "conformance/mpr_replay.hpp"
#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"

#ifndef MPR_SOURCE_DIR
#error "MPR_SOURCE_DIR must point at the source tree"
#endif

namespace mpr {
namespace {

std::vector<BufferSet> runThroughExecutor(const Script& script) {
  GLContext gl(script.width, script.height, mesaProfile());
  std::vector<BufferSet> out;
  ScriptHooks hooks;
  hooks.onSnapshot = [&](const ScriptCommand& c, const GLContext& context) {
    out.push_back(collectBuffers(c.label, context.framebuffer()));
  };
  runScript(script, gl, hooks);
  out.push_back(collectBuffers("final", gl.framebuffer()));
  return out;
}

std::vector<std::filesystem::path> corpusAndReproducers() {
  const std::filesystem::path dir = std::filesystem::path(MPR_SOURCE_DIR) / "tests" / "conformance";
  std::vector<std::filesystem::path> files;
  for (const auto& folder : {dir, dir / "repro"})
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".gls") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(RunnerReplayAgreement, MprGlWritesWhatMprConformComparesOnEveryCorpusScript) {
  const auto files = corpusAndReproducers();
  ASSERT_GE(files.size(), 50u);
  for (const auto& file : files) {
    const Script script = loadScript(file.string());
    const std::vector<BufferSet> executed = runThroughExecutor(script);
    const MprReplay replayed = replayOnMpr(script, mesaProfile());
    ASSERT_EQ(executed.size(), replayed.snapshots.size()) << file;
    for (std::size_t i = 0; i < executed.size(); ++i) {
      const BufferSet &a = executed[i], &b = replayed.snapshots[i];
      const std::string where = file.filename().string() + " at " + a.point;
      EXPECT_EQ(a.point, b.point) << where;
      EXPECT_TRUE(a.color == b.color) << where << ": colour differs";
      EXPECT_TRUE(a.depth == b.depth) << where << ": depth differs";
      EXPECT_TRUE(a.stencil == b.stencil) << where << ": stencil differs";
    }
  }
}

}  // namespace
}  // namespace mpr
