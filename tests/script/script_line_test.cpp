// nextScriptLine (lines and tokens cut from bit masks of 64 bytes) against
// scriptLineOneByOne (a character at a time): on random texts of the
// characters that matter to the cut (space, tab, '#', '\r', '\n') and two
// that do not, from every starting line, the same line, the same tokens (the
// same characters of the text, not equal copies), the same next line and end.
// Lines shorter and longer than 64 bytes, lines that end within the last 64
// bytes and a text without a final '\n' all occur; the per-line checks pin
// the spec's rules (gl-script.md) on which both rest.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "script/script_line.hpp"

namespace mpr {
namespace {

void expectSameCut(std::string_view text, std::size_t pos) {
  std::vector<ScriptToken> fast, slow;
  fast.push_back({"stale", 9});  // both clear the vector first
  const ScriptLine a = nextScriptLine(text, pos, fast);
  const ScriptLine b = scriptLineOneByOne(text, pos, slow);
  const std::string where = "at " + std::to_string(pos) + " of \"" + std::string(text) + "\"";
  ASSERT_EQ(a.text.data(), b.text.data()) << where;
  ASSERT_EQ(a.text.size(), b.text.size()) << where;
  ASSERT_EQ(a.next, b.next) << where;
  ASSERT_EQ(a.last, b.last) << where;
  ASSERT_EQ(fast.size(), slow.size()) << where;
  for (std::size_t i = 0; i < fast.size(); ++i) {
    ASSERT_EQ(fast[i].text.data(), slow[i].text.data()) << where << " token " << i;
    ASSERT_EQ(fast[i].text.size(), slow[i].text.size()) << where << " token " << i;
    ASSERT_EQ(fast[i].column, slow[i].column) << where << " token " << i;
  }
}

std::vector<std::string> tokensOf(std::string_view text, std::size_t pos = 0) {
  std::vector<ScriptToken> tokens;
  nextScriptLine(text, pos, tokens);
  std::vector<std::string> out;
  for (const ScriptToken& t : tokens) out.emplace_back(t.text);
  return out;
}

TEST(ScriptLine, RulesOfTheFormat) {
  // Padded past 64 bytes so that the mask path cuts the first line.
  const std::string pad(80, 'x');
  std::vector<ScriptToken> tokens;
  const std::string text = "\tglRectf  -1 1#c d\r\n" + pad;
  const ScriptLine line = nextScriptLine(text, 0, tokens);
  EXPECT_EQ(line.text, "\tglRectf  -1 1#c d");
  EXPECT_EQ(line.next, 20u);
  EXPECT_FALSE(line.last);
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].text, "glRectf");
  EXPECT_EQ(tokens[0].column, 2);
  EXPECT_EQ(tokens[1].text, "-1");
  EXPECT_EQ(tokens[1].column, 11);
  EXPECT_EQ(tokens[2].text, "1");  // '#' ends the token and starts the comment
  EXPECT_EQ(tokens[2].column, 14);
  // A '\r' not before the '\n' belongs to its token; only one is dropped.
  EXPECT_EQ(tokensOf("a\rb\r\r\n" + pad), (std::vector<std::string>{"a\rb\r"}));
  // The last line, without a '\n': next is one past the text's end.
  const ScriptLine end = nextScriptLine("glFinish", 0, tokens);
  EXPECT_TRUE(end.last);
  EXPECT_EQ(end.next, 9u);
  EXPECT_EQ(tokensOf("# all comment\n" + pad).size(), 0u);
}

TEST(ScriptLine, MasksCutAsTheCharacterLoop) {
  const char alphabet[] = {' ', '\t', '#', '\r', '\n', 'a', '1'};
  std::mt19937 rng(20261204);
  for (int round = 0; round < 3000; ++round) {
    // Some texts of long lines (rare '\n'), some of short ones.
    const int newlineOdds = round % 3 == 0 ? 200 : 12;
    const std::size_t length = rng() % 300;
    std::string text;
    for (std::size_t i = 0; i < length; ++i)
      text += rng() % newlineOdds == 0 ? '\n' : alphabet[rng() % 7];
    if (round % 2 == 0) text += '\n';
    std::size_t pos = 0;
    std::vector<ScriptToken> tokens;
    while (pos <= text.size()) {
      expectSameCut(text, pos);
      if (HasFatalFailure()) return;
      pos = nextScriptLine(text, pos, tokens).next;
    }
    // A line may also be asked for from any offset (a '\n' just passed or not).
    for (std::size_t p = 0; p <= text.size(); p += 7) {
      expectSameCut(text, p);
      if (HasFatalFailure()) return;
    }
  }
}

}  // namespace
}  // namespace mpr
