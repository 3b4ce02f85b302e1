// ScriptExecutor::executeCall (a call given by its parts, as `mpr gl` runs
// the calls it streams) against execute (the command whole): on every
// script of the conformance corpus, gl_errors.gls among them, the same GL
// error reports, the same error count and the same buffers, byte for byte;
// and a beforeCall hook, which needs the command, makes it decline.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"

namespace mpr {
namespace {

struct ScriptRun {
  std::vector<std::string> reports;
  std::size_t errors = 0;
  std::vector<Rgba8> color;
  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> stencil;
  std::vector<std::int16_t> accum;
};

ScriptRun runScriptCalls(const Script& script, bool byParts) {
  const HardwareProfile profile = findProfile(script.profile.value_or("mesa")).value_or(mesaProfile());
  GLContext gl(script.width, script.height, profile);
  ScriptRun run;
  ScriptHooks hooks;
  hooks.onGLError = [&](const ScriptCommand& c, std::uint32_t e) { run.reports.push_back(glErrorReport(c, e)); };
  ScriptExecutor executor(gl, hooks);
  for (const ScriptCommand& c : script.commands) {
    if (byParts && c.kind == ScriptCommand::Kind::Call) {
      EXPECT_TRUE(executor.executeCall(c.call, c.line, c.args));
      continue;
    }
    executor.execute(c);
  }
  run.errors = executor.finish();
  const Framebuffer& fb = gl.framebuffer();
  run.color = fb.colorData();
  run.depth = fb.depthData();
  run.stencil = fb.stencilData();
  run.accum = fb.accumData();
  return run;
}

TEST(ScriptExecutor, ACallByItsPartsRunsAndReportsAsTheWholeCommand) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  int scripts = 0;
  bool sawErrors = false;
  for (const auto& entry : std::filesystem::directory_iterator(root / "tests/conformance")) {
    if (entry.path().extension() != ".gls") continue;
    const std::string path = entry.path().string();
    const Script script = parseScript(readScriptText(path), path);
    const ScriptRun whole = runScriptCalls(script, false), parts = runScriptCalls(script, true);
    EXPECT_EQ(parts.reports, whole.reports) << path;
    EXPECT_EQ(parts.errors, whole.errors) << path;
    ASSERT_EQ(parts.color, whole.color) << path;
    ASSERT_EQ(parts.depth, whole.depth) << path;
    ASSERT_EQ(parts.stencil, whole.stencil) << path;
    ASSERT_EQ(parts.accum, whole.accum) << path;
    sawErrors = sawErrors || !whole.reports.empty();
    ++scripts;
  }
  EXPECT_GT(scripts, 15);
  EXPECT_TRUE(sawErrors);  // gl_errors.gls reports some
}

TEST(ScriptExecutor, ABeforeCallHookMakesACallByItsPartsDecline) {
  const Script script = parseScript("@framebuffer 4 4\nglClearColor 1 0 0 1\nglClear GL_COLOR_BUFFER_BIT\n", "s.gls");
  GLContext gl(script.width, script.height, mesaProfile());
  ScriptHooks hooks;
  int seen = 0;
  hooks.beforeCall = [&](const ScriptCommand&) { ++seen; };
  ScriptExecutor executor(gl, hooks);
  for (const ScriptCommand& c : script.commands) EXPECT_FALSE(executor.executeCall(c.call, c.line, c.args));
  executor.finish();
  EXPECT_EQ(seen, 0);
  EXPECT_EQ(gl.colorAt(0, 0), (Rgba8{0, 0, 0, 0}));  // nothing ran
}

}  // namespace
}  // namespace mpr
