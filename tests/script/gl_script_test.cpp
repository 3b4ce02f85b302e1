// Parsing of the GL script format (spec/gl-script.md) and execution on a context.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"
#include "script/script_text.hpp"

namespace mpr {
namespace {

TEST(GLScript, ParsesCallsArgumentsAndDirectives) {
  const Script s = parseScript(
      "# comment\n"
      "@framebuffer 8 4\r\n"
      "@profile mesa\n"
      "\n"
      "  glStencilFunc GL_LESS 128 0xFF   # trailing comment\n"
      "@pass mirror mask level 1\n"
      "glClear GL_COLOR_BUFFER_BIT|GL_STENCIL_BUFFER_BIT\n"
      "glClearColor 0.5 1e-3 -2 1.0f\n"
      "glLightfv GL_LIGHT0 GL_POSITION 0 10 0 1\n"
      "@snapshot after-clear\n",
      "t.gls");
  EXPECT_EQ(s.width, 8);
  EXPECT_EQ(s.height, 4);
  EXPECT_EQ(s.profile.value_or(""), "mesa");
  ASSERT_EQ(s.commands.size(), 6u);
  const ScriptCommand& f = s.commands[0];
  EXPECT_EQ(f.call, GLCall::StencilFunc);
  EXPECT_EQ(f.line, 5);
  EXPECT_EQ(f.args[0].bits, static_cast<std::uint32_t>(GL_LESS));
  EXPECT_EQ(f.args[1].bits, 128u);
  EXPECT_EQ(f.args[2].bits, 0xFFu);
  EXPECT_EQ(f.args[2].column, 29);
  EXPECT_EQ(s.commands[1].kind, ScriptCommand::Kind::Pass);
  EXPECT_EQ(s.commands[1].label, "mirror mask level 1");
  EXPECT_EQ(s.commands[2].args[0].bits, static_cast<std::uint32_t>(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT));
  EXPECT_EQ(s.commands[3].args[1].number, 1e-3);
  EXPECT_EQ(s.commands[3].args[2].number, -2.0);
  EXPECT_EQ(s.commands[3].args[3].number, 1.0);
  EXPECT_EQ(s.commands[4].args.size(), 6u);
  EXPECT_EQ(s.commands[5].kind, ScriptCommand::Kind::Snapshot);
  EXPECT_EQ(s.commands[5].label, "after-clear");
  EXPECT_EQ(s.callCount(), 4u);
}

TEST(GLScript, DefaultsTo256SquareAndNoProfile) {
  const Script s = parseScript("glFinish\n", "t.gls");
  EXPECT_EQ(s.width, 256);
  EXPECT_EQ(s.height, 256);
  EXPECT_FALSE(s.profile.has_value());
}

TEST(GLScript, ErrorsCarryLineAndColumn) {
  try {
    parseScript("glFinish\n  glStencilOp GL_KEEP GL_KEEP GL_REPLAC\n", "f.gls");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 31);
    EXPECT_STREQ(e.what(), "f.gls:2:31: unknown GL enumerant 'GL_REPLAC' (argument 3 of glStencilOp)");
  }
}

// Issue 48: a UTF-8 byte-order mark before the first line (as some editors
// save files) is skipped; it made line 1's first token an unknown call.
// Columns on line 1 count from after it; one anywhere else is a token's.
TEST(GLScript, SkipsALeadingByteOrderMark) {
  const Script s = parseScript("\xEF\xBB\xBF@framebuffer 8 4\nglClear GL_COLOR_BUFFER_BIT\n", "b.gls");
  EXPECT_EQ(s.width, 8);
  EXPECT_EQ(s.height, 4);
  ASSERT_EQ(s.commands.size(), 1u);
  EXPECT_EQ(s.commands[0].line, 2);
  const Script call = parseScript("\xEF\xBB\xBFglClearStencil 7\n", "b.gls");
  ASSERT_EQ(call.commands.size(), 1u);
  EXPECT_EQ(call.commands[0].args[0].column, 16);
  try {
    parseScript("\xEF\xBB\xBFglClearStencil x\n", "b.gls");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.column(), 16);
  }
  // Only at the very start: a second one is text.
  EXPECT_THROW(parseScript("glFinish\n\xEF\xBB\xBFglFinish\n", "b.gls"), ScriptError);
  EXPECT_THROW(parseScript("\xEF\xBB\xBF\xEF\xBB\xBFglFinish\n", "b.gls"), ScriptError);
  // Read in pieces (a file a piece at a time), and read again after a rewind.
  const std::string text = "\xEF\xBB\xBFglFinish\nglFlush\n";
  ScriptText pieces = ScriptText::ofString(text, 1);
  EXPECT_EQ(checkScript(pieces, "b.gls").width, 256);
  EXPECT_EQ(checkScript(pieces, "b.gls").width, 256);
}

TEST(GLScript, RunsOnAContextAndReportsGLErrors) {
  const Script s = parseScript(
      "@framebuffer 4 4\n"
      "glEnable GL_STENCIL_TEST\n"
      "glStencilFunc GL_ALWAYS 3 0xFF\n"
      "glStencilOp GL_KEEP GL_KEEP GL_REPLACE\n"
      "glMatrixMode GL_PROJECTION\n"
      "glOrtho 0 4 0 4 -1 1\n"
      "glMatrixMode GL_MODELVIEW\n"
      "glRectf 1 1 3 3\n"
      "glPopMatrix\n",
      "r.gls");
  GLContext gl(s.width, s.height, indigoProfile());
  std::vector<int> errorLines;
  ScriptHooks hooks;
  hooks.onGLError = [&](const ScriptCommand& c, std::uint32_t e) {
    EXPECT_EQ(e, static_cast<std::uint32_t>(GL_STACK_UNDERFLOW));
    errorLines.push_back(c.line);
  };
  EXPECT_EQ(runScript(s, gl, hooks), 1u);
  EXPECT_EQ(errorLines, std::vector<int>{9});
  EXPECT_EQ(gl.stencilAt(1, 1), 3u);
  EXPECT_EQ(gl.stencilAt(2, 2), 3u);
  EXPECT_EQ(gl.stencilAt(0, 0), 0u);
  EXPECT_EQ(gl.stencilAt(3, 3), 0u);
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

// Numbers are read by a fast path (short plain decimals, Clinger's) and by
// from_chars/strtod otherwise: every spelling must give strtod's double, bit
// for bit, whichever path reads it: random digits, points, exponents and
// signs, across the fast path's edges (15 digits, exponents of +-22).
TEST(GLScript, NumbersReadAsStrtodReadsThemOnEveryPath) {
  std::mt19937 rng(1997);
  std::string text = "@framebuffer 4 4\n";
  std::vector<std::string> written;
  for (int i = 0; i < 20000; ++i) {
    std::string n;
    if (rng() % 2) n += '-';
    const int intDigits = static_cast<int>(rng() % 10), fracDigits = static_cast<int>(rng() % 12);
    for (int d = 0; d < intDigits; ++d) n += static_cast<char>('0' + rng() % 10);
    if (fracDigits > 0 || rng() % 4 == 0) n += '.';
    for (int d = 0; d < fracDigits; ++d) n += static_cast<char>('0' + rng() % 10);
    if (intDigits + fracDigits == 0) n += '7';
    if (rng() % 3 == 0) {
      n += rng() % 2 ? 'e' : 'E';
      const int sign = static_cast<int>(rng() % 3);
      if (sign == 1) n += '-';
      if (sign == 2) n += '+';
      n += std::to_string(rng() % 40);
    }
    written.push_back(n);
    text += "glVertex3f " + n + " 0 0\n";
  }
  const Script s = parseScript(text, "numbers.gls");
  ASSERT_EQ(s.commands.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    const double want = std::strtod(written[i].c_str(), nullptr);
    const double got = s.commands[i].args[0].number;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want)) << written[i];
  }
}

}  // namespace
}  // namespace mpr
