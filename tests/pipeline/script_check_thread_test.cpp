// What `mpr gl` with more than one thread starts from instead of a whole
// check: scanScriptHeader throws checkScript's error where the first error
// stands before the first call, and nothing where it stands after (that it
// gives checkScript's header on every script of the repository is
// script_stream_test's);
// ScriptCheckThread reports checkScript's error, or none, whenever it is
// waited for.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/gl_script.hpp"
#include "pipeline/script_check_thread.hpp"

namespace mpr {
namespace {

// The message of the ScriptError that waiting for `check` throws, or "".
std::string errorOf(ScriptCheckThread& check) {
  try {
    check.wait();
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "";
}

// The message of the ScriptError `read` throws on `text`, or "".
std::string errorOf(Script (*read)(std::string_view, const std::string&), const std::string& text) {
  try {
    read(text, "s.gls");
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "";
}
std::string checkError(const std::string& text) { return errorOf(checkScript, text); }
std::string headerError(const std::string& text) { return errorOf(scanScriptHeader, text); }

TEST(ScriptHeader, ThrowsCheckScriptsErrorOnlyBeforeTheFirstCall) {
  // The first error before the first call, in directives of every kind.
  for (const std::string text : {"@framebuffer 8\nglFinish\n", "@profile nope\n", "@framebuffer 8 8\n@pass\n",
                                 "@snapshot a\n@snapshot a\nglFinish\n", "@framebuffer 8 8\n@framebuffer 8 8\n",
                                 "@expect stencil 1\n", "@end\nglFinish\n", "@framebuffer 70000 8\n"}) {
    const std::string expected = checkError(text);
    EXPECT_FALSE(expected.empty()) << text;
    EXPECT_EQ(headerError(text), expected) << text;
  }
  // An error at or after the first call is not the header's; neither is a
  // probe outside the window, known only once the whole script is read.
  for (const std::string text : {"@framebuffer 8 8\nglFinsh\n", "glFinish\n@framebuffer 8 8\n",
                                 "@framebuffer 8 8\nglFinish\nglStencilFunc GL_LESS 1\n",
                                 "@expect stencil 300 0 1\nglFinish\n"}) {
    EXPECT_FALSE(checkError(text).empty()) << text;
    EXPECT_EQ(headerError(text), "") << text;
  }
  // A script without a call is its header: checked whole, the checks at its
  // end included.
  for (const std::string text : {"@expect stencil 300 0 1\n", "@expect-picture stencil 0 0\n1 1\n"}) {
    const std::string expected = checkError(text);
    EXPECT_FALSE(expected.empty()) << text;
    EXPECT_EQ(headerError(text), expected) << text;
  }
  const Script header = scanScriptHeader("# c\n@profile mesa\n@framebuffer 12 7\n@pass a\nglFinish\nglFoo\n", "s.gls");
  EXPECT_EQ(header.width, 12);
  EXPECT_EQ(header.height, 7);
  EXPECT_EQ(header.profile, "mesa");
}

TEST(ScriptCheckThread, ReportsCheckScriptsErrorOrNone) {
  std::string longValid = "@framebuffer 8 8\n";
  for (int i = 0; i < 20000; ++i) longValid += "glRectf 0 0 0." + std::to_string(i) + " 1\n";
  for (const std::string& text : {longValid, longValid + "glRectf 0 0 1\n", longValid + "@expect stencil 9 9 0\n",
                                 std::string("glFoo\n"), std::string("")}) {
    const std::string expected = checkError(text);
    ScriptCheckThread check(text, "s.gls");
    EXPECT_EQ(errorOf(check), expected) << text.substr(text.size() > 40 ? text.size() - 40 : 0);
    EXPECT_EQ(check.passed(), expected.empty());
    EXPECT_EQ(check.failed(), !expected.empty());
    EXPECT_EQ(errorOf(check), expected);  // again: the same answer
  }
  // Destroyed while it runs: waited for, nothing left behind.
  { ScriptCheckThread unwaited(longValid, "s.gls"); }
}

}  // namespace
}  // namespace mpr
