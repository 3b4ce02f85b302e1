// RecentLines hands back a call line's command only for the same bytes, and
// a script whose lines repeat parses to the commands each line gives alone:
// the same call, arguments (to the bit) and columns, at the right line
// numbers, in the stored and the streamed parse, with an error after many
// repeated lines still at its own line.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "script/gl_script.hpp"
#include "script/recent_lines.hpp"

namespace mpr {
namespace {

// `line` then '\n' and enough other bytes for find's 64-byte read.
std::string padded(const std::string& line, const std::string& after = std::string(64, 'x')) {
  return line + "\n" + after;
}

TEST(RecentLines, FindsOnlyTheSameBytes) {
  RecentLines recent;
  const std::string first = padded("glVertex3f 1 2 3");
  EXPECT_EQ(recent.find(first, 0), nullptr);
  const ScriptArg args[3] = {{1.0, 0, 12}, {2.0, 0, 14}, {3.0, 0, 16}};
  recent.keep(GLCall::Vertex3f, args);
  // The same line elsewhere, other bytes after it.
  const std::string again = "glEnd\n" + padded("glVertex3f 1 2 3", std::string(70, '7'));
  const RecentLines::Entry* kept = recent.find(again, 6);
  ASSERT_NE(kept, nullptr);
  EXPECT_EQ(kept->size, 16u);
  EXPECT_EQ(kept->call, GLCall::Vertex3f);
  ASSERT_EQ(kept->argCount, 3);
  EXPECT_EQ(kept->args[2].number, 3.0);
  EXPECT_EQ(kept->args[2].column, 16);
  // One byte, one byte more or less, a '\r', a comment: not the same line.
  for (const char* other : {"glVertex3f 1 2 4", "glVertex3f 1 2 33", "glVertex3f 1 2 ", "glVertex3f 1 2 3\r",
                            "glVertex3f 1 2 3 # c", " glVertex3f 1 2 3"})
    EXPECT_EQ(recent.find(padded(other), 0), nullptr) << other;
}

TEST(RecentLines, KeepsNoLongLineNorManyArguments) {
  RecentLines recent;
  const std::string longLine = "glVertex3f 0.1234567890123456 0.1234567890123456 0.12345678901234567";
  ASSERT_GT(longLine.size(), RecentLines::kMaxBytes);
  EXPECT_EQ(recent.find(padded(longLine), 0), nullptr);
  recent.keep(GLCall::Vertex3f, std::vector<ScriptArg>(3));
  EXPECT_EQ(recent.find(padded(longLine), 0), nullptr);
  const std::string many = "glMaterialfv GL_FRONT GL_DIFFUSE 1 1 1 1";
  EXPECT_EQ(recent.find(padded(many), 0), nullptr);
  recent.keep(GLCall::Materialfv, std::vector<ScriptArg>(6));
  EXPECT_EQ(recent.find(padded(many), 0), nullptr);
  // Fewer than 64 bytes to read: not looked up.
  EXPECT_EQ(recent.find("glEnd\n", 0), nullptr);
  // keep() without a missed find() before it keeps nothing.
  recent.keep(GLCall::End, {});
  EXPECT_EQ(recent.find(padded("glEnd"), 0), nullptr);
}

void expectSameCommand(const ScriptCommand& got, const ScriptCommand& want, int line) {
  EXPECT_EQ(got.kind, want.kind) << "line " << line;
  EXPECT_EQ(got.call, want.call) << "line " << line;
  EXPECT_EQ(got.line, line);
  ASSERT_EQ(got.args.size(), want.args.size()) << "line " << line;
  for (std::size_t i = 0; i < got.args.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got.args[i].number), std::bit_cast<std::uint64_t>(want.args[i].number))
        << "line " << line << " argument " << i + 1;
    EXPECT_EQ(got.args[i].bits, want.args[i].bits) << "line " << line << " argument " << i + 1;
    EXPECT_EQ(got.args[i].column, want.args[i].column) << "line " << line << " argument " << i + 1;
  }
}

// A few thousand lines drawn from a pool of call lines (numbers in several
// spellings, enums, tabs, comments, '\r', lines past 63 bytes, more than 4
// arguments), so that most repeat one before them and many share a slot.
std::vector<std::string> repeatedLines() {
  std::mt19937 rng(2207);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const char* spellings[] = {"0", "1", "-1", "0.5", "-0.25", ".5", "1e-3", "2.5f", "0x10", "3.0000001", "-7.125"};
  std::vector<std::string> pool;
  for (int i = 0; i < 1500; ++i) {
    std::string line;
    switch (pick(8)) {
      case 0: line = "glNormal3f"; break;
      case 1: line = "glColor4f"; break;
      case 2: line = "glBegin GL_TRIANGLES"; break;
      case 3: line = "glEnd"; break;
      case 4: line = "glMaterialfv GL_FRONT GL_AMBIENT"; break;
      default: line = "glVertex3f"; break;
    }
    const int numbers = line == "glNormal3f" || line == "glVertex3f" ? 3 : line == "glEnd" || line[2] == 'B' ? 0 : 4;
    for (int k = 0; k < numbers; ++k) {
      line += pick(6) ? " " : "\t";
      line += pick(3) ? std::to_string(pick(4000) - 2000) + "." + std::to_string(pick(100000))
                      : std::string(spellings[pick(11)]);
    }
    if (pick(10) == 0) line = "  " + line;
    if (pick(10) == 0) line += "  # a comment";
    if (pick(12) == 0) line += "\r";
    pool.push_back(line);
  }
  std::vector<std::string> lines;
  for (int i = 0; i < 6000; ++i) lines.push_back(pool[static_cast<std::size_t>(pick(pick(4) ? 200 : 1500))]);
  return lines;
}

TEST(RecentLines, RepeatedLinesParseAsEachLineAlone) {
  const std::vector<std::string> lines = repeatedLines();
  std::string text = "@framebuffer 16 16\n";
  for (const std::string& l : lines) text += l + "\n";
  const Script stored = parseScript(text, "t.gls");
  std::vector<ScriptCommand> streamed;
  streamScript(text, stored, [&](ScriptCommand&& c) { streamed.push_back(std::move(c)); });
  ASSERT_EQ(stored.commands.size(), lines.size());
  ASSERT_EQ(streamed.size(), lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Script alone = parseScript(lines[i] + "\n", "alone.gls");
    ASSERT_EQ(alone.commands.size(), 1u);
    const int line = static_cast<int>(i) + 2;
    ScriptCommand want = alone.commands[0];
    want.line = line;
    expectSameCommand(stored.commands[i], want, line);
    expectSameCommand(streamed[i], want, line);
  }
}

TEST(RecentLines, AnErrorAfterRepeatedLinesIsAtItsLine) {
  std::string text;
  for (int i = 0; i < 500; ++i) text += i % 2 ? "glVertex3f 1 2 3\n" : "glNormal3f 0 0 1\n";
  text += "glVertex3f 1 2\n";
  for (int i = 0; i < 10; ++i) text += "glVertex3f 1 2 3\n";
  try {
    parseScript(text, "t.gls");
    FAIL() << "a vertex with two numbers parsed";
  } catch (const ScriptError& e) {
    EXPECT_EQ(e.line(), 501);
    EXPECT_EQ(e.column(), 15);
  }
}

}  // namespace
}  // namespace mpr
