// streamScript against parseScript: on every script of the conformance
// corpus, its reproducers, the probe scripts (pixels, rectangles, `all`,
// pictures) and scenes/, the streamed commands are parseScript's, in the
// same order, field for field, probes placed alike; checkScript keeps no
// command and reports a bad script's error where parseScript does.
#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <vector>

#include "pipeline/gl_script.hpp"

namespace mpr {
namespace {

void expectSameCommand(const ScriptCommand& a, const ScriptCommand& b, const std::string& where) {
  ASSERT_EQ(a.kind, b.kind) << where;
  ASSERT_EQ(a.line, b.line) << where;
  ASSERT_EQ(a.call, b.call) << where;
  ASSERT_EQ(a.label, b.label) << where;
  ASSERT_EQ(a.args.size(), b.args.size()) << where;
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    ASSERT_EQ(a.args[i].bits, b.args[i].bits) << where;
    ASSERT_EQ(a.args[i].column, b.args[i].column) << where;
    ASSERT_EQ(a.args[i].text, b.args[i].text) << where;
    // Bit for bit (NaN and -0 included).
    ASSERT_EQ(std::bit_cast<std::uint64_t>(a.args[i].number), std::bit_cast<std::uint64_t>(b.args[i].number)) << where;
  }
  ASSERT_EQ(a.probe == nullptr, b.probe == nullptr) << where;
  if (a.probe) {
    ASSERT_EQ(a.probe->buffer, b.probe->buffer) << where;
    ASSERT_EQ(a.probe->form, b.probe->form) << where;
    ASSERT_EQ(a.probe->region.x0, b.probe->region.x0) << where;
    ASSERT_EQ(a.probe->region.y0, b.probe->region.y0) << where;
    ASSERT_EQ(a.probe->region.x1, b.probe->region.x1) << where;
    ASSERT_EQ(a.probe->region.y1, b.probe->region.y1) << where;
    ASSERT_EQ(a.probe->expected, b.probe->expected) << where;
    ASSERT_EQ(a.probe->cells, b.probe->cells) << where;
    ASSERT_EQ(a.probe->tolerance, b.probe->tolerance) << where;
  }
}

TEST(ScriptStream, CommandsAreParseScriptsOnEveryScriptOfTheRepository) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  int scripts = 0, probes = 0;
  for (const char* folder : {"tests/conformance", "tests/conformance/repro", "tests/probes/pass", "tests/probes/fail",
                             "scenes"})
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      if (entry.path().extension() != ".gls") continue;
      const std::string path = entry.path().string();
      const std::string text = readScriptText(path);
      const Script stored = parseScript(text, path);
      const Script header = checkScript(text, path);
      EXPECT_TRUE(header.commands.empty()) << path;
      EXPECT_EQ(header.width, stored.width) << path;
      EXPECT_EQ(header.height, stored.height) << path;
      EXPECT_EQ(header.profile, stored.profile) << path;
      std::vector<ScriptCommand> streamed;
      streamScript(text, header, [&](ScriptCommand&& c) { streamed.push_back(std::move(c)); });
      ASSERT_EQ(streamed.size(), stored.commands.size()) << path;
      for (std::size_t i = 0; i < streamed.size(); ++i) {
        expectSameCommand(streamed[i], stored.commands[i], path + " command " + std::to_string(i));
        probes += streamed[i].probe != nullptr;
      }
      ++scripts;
    }
  EXPECT_GT(scripts, 50);
  EXPECT_GT(probes, 10);  // the probe forms were among them
}

TEST(ScriptStream, CheckScriptReportsTheErrorParseScriptReports) {
  // A probe outside the window is only known once @framebuffer is read.
  for (const std::string text :
       {"@framebuffer 8 8\nglClear GL_STENCIL_BUFFER_BIT\nglStencilFunc GL_LESS 1\n",
        "@expect stencil 9 0 1\n@framebuffer 8 8\n",
        "@framebuffer 8 8\n@expect-picture stencil 0 0\n1 1\n",
        "@framebuffer 4 4\nglBegin GL_TRIANGLES\nglVertex3f 0 0 nope\nglEnd\n"}) {
    std::string parseMessage, checkMessage;
    try {
      parseScript(text, "bad.gls");
    } catch (const ScriptError& e) {
      parseMessage = e.what();
    }
    try {
      checkScript(text, "bad.gls");
    } catch (const ScriptError& e) {
      checkMessage = e.what();
    }
    EXPECT_FALSE(parseMessage.empty()) << text;
    EXPECT_EQ(checkMessage, parseMessage) << text;
  }
}

}  // namespace
}  // namespace mpr
