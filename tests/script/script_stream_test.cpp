// streamScript against parseScript: on every script of the conformance
// corpus, its reproducers, the probe scripts (pixels, rectangles, `all`,
// pictures) and scenes/, the streamed commands are parseScript's, in the
// same order, field for field, probes placed alike; checkScript keeps no
// command and reports a bad script's error where parseScript does, and
// scanScriptHeader gives its header; with a call sink, the calls reach it
// as their parts, in the same order;
// streamScriptAhead (the parsing on a thread of its own) hands on
// streamScript's commands, stops when the sink throws and reports a read
// error after the commands before it. What `mpr gl` with more than one
// thread relies on instead of a whole check first: scanScriptHeader throws
// checkScript's error where the first error stands before the first call,
// and from its header the reading throws checkScript's error on every
// script, thousands of broken ones included. Read in pieces of whole
// lines (ScriptText: a file a piece at a time), of any size from one byte,
// every script parses and fails as its whole text does.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <span>
#include <vector>

#include "script/gl_script.hpp"
#include "script/script_read_ahead.hpp"
#include "script/script_text.hpp"
#include "testing/temp_folder.hpp"

namespace mpr {
namespace {

// a streamed, b as streamed or stored.
void expectSameCommand(const ScriptCommand& a, const ScriptCommand& b, const std::string& where) {
  ASSERT_EQ(a.kind, b.kind) << where;
  ASSERT_EQ(a.line, b.line) << where;
  ASSERT_EQ(a.call, b.call) << where;
  ASSERT_EQ(a.label, b.label) << where;
  ASSERT_EQ(a.args.size(), b.args.size()) << where;
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    ASSERT_EQ(a.args[i].bits, b.args[i].bits) << where;
    ASSERT_EQ(a.args[i].column, b.args[i].column) << where;
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
  int scripts = 0, probes = 0, sized = 0, profiled = 0;
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
      // What `mpr gl` starts from when the check runs beside it.
      const Script scanned = scanScriptHeader(text, path);
      EXPECT_TRUE(scanned.commands.empty()) << path;
      EXPECT_EQ(scanned.file, header.file) << path;
      EXPECT_EQ(scanned.width, stored.width) << path;
      EXPECT_EQ(scanned.height, stored.height) << path;
      EXPECT_EQ(scanned.profile, stored.profile) << path;
      sized += stored.width != 256 || stored.height != 256;
      profiled += stored.profile.has_value();
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
  EXPECT_GT(sized, 10);   // and headers of both kinds
  EXPECT_GT(profiled, 10);
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

// A script longer than the batches in flight (1024 commands each, four at
// a time), with directives and probes among the calls.
std::string longScript(int lines) {
  std::string text = "@framebuffer 16 16\n";
  for (int i = 0; i < lines; ++i) {
    if (i % 997 == 0) text += "@pass p" + std::to_string(i) + "\n";
    if (i % 1511 == 0) text += "@expect stencil 1 1 0\n";
    text += "glBegin GL_TRIANGLES\nglVertex3f 0." + std::to_string(i) + " -1e-" + std::to_string(i % 30) +
            " 0\nglVertex2f 1 0\nglVertex3f 0 1 " + std::to_string(i) + "\nglEnd\n";
  }
  return text;
}

using NamedScripts = std::vector<std::pair<std::string, std::string>>;

// `scripts`, then every script of the repository's folders `folders`
// (paths from the source tree), each with its text.
NamedScripts withRepositoryScripts(NamedScripts scripts, std::initializer_list<const char*> folders) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  for (const char* folder : folders)
    for (const auto& entry : std::filesystem::directory_iterator(root / folder))
      if (entry.path().extension() == ".gls")
        scripts.push_back({entry.path().string(), readScriptText(entry.path().string())});
  return scripts;
}

TEST(ScriptStream, AheadHandsOnStreamScriptsCommandsInOrder) {
  const NamedScripts scripts = withRepositoryScripts(
      {{"long.gls", longScript(3000)}}, {"tests/conformance", "tests/conformance/repro", "tests/probes/pass", "scenes"});
  for (const auto& [path, text] : scripts) {
    const Script header = checkScript(text, path);
    std::vector<ScriptCommand> plain, ahead, aheadMoved;
    streamScript(text, header, [&](ScriptCommand&& c) { plain.push_back(c); });
    // A sink that copies and one that moves the command away.
    streamScriptAhead(text, header, [&](ScriptCommand&& c) { ahead.push_back(c); });
    streamScriptAhead(text, header, [&](ScriptCommand&& c) { aheadMoved.push_back(std::move(c)); });
    ASSERT_EQ(ahead.size(), plain.size()) << path;
    ASSERT_EQ(aheadMoved.size(), plain.size()) << path;
    for (std::size_t i = 0; i < plain.size(); ++i) {
      expectSameCommand(ahead[i], plain[i], path + " command " + std::to_string(i));
      expectSameCommand(aheadMoved[i], plain[i], path + " command " + std::to_string(i) + " (moved)");
    }
  }
  EXPECT_GT(scripts.size(), 50u);
}

// With a call sink, each packed call is offered to it as its parts first;
// the ones it takes do not reach the command sink, the rest do, and the
// two together are streamScript's commands in order.
TEST(ScriptStream, AheadOffersEachCallAsItsPartsAndSendsOnWhatIsNotTaken) {
  const NamedScripts scripts =
      withRepositoryScripts({{"long.gls", longScript(3000)}}, {"tests/conformance", "tests/probes/pass", "scenes"});
  for (const auto& [path, text] : scripts) {
    const Script header = checkScript(text, path);
    std::vector<ScriptCommand> plain, ahead;
    streamScript(text, header, [&](ScriptCommand&& c) { plain.push_back(c); });
    std::size_t taken = 0, offered = 0;
    ScriptText whole = ScriptText::ofString(text);
    streamScriptAhead(
        whole, header, [&](ScriptCommand&& c) { ahead.push_back(std::move(c)); },
        [&](GLCall call, int line, std::span<const ScriptArg> args) {
          ++offered;
          if (line % 3 == 0) return false;  // declined: goes to the command sink
          ScriptCommand c;
          c.line = line;
          c.call = call;
          c.args.assign(args.begin(), args.end());
          ahead.push_back(std::move(c));
          ++taken;
          return true;
        });
    ASSERT_EQ(ahead.size(), plain.size()) << path;
    std::size_t calls = 0;
    for (std::size_t i = 0; i < plain.size(); ++i) {
      calls += plain[i].kind == ScriptCommand::Kind::Call;
      expectSameCommand(ahead[i], plain[i], path + " command " + std::to_string(i));
    }
    EXPECT_EQ(offered, calls) << path;  // every call is offered (none is too long to pack here)
    EXPECT_GT(taken, 0u) << path;
  }
}

TEST(ScriptStream, AheadStopsWhenTheSinkThrowsAndReportsReadErrorsAfterTheCommandsBeforeThem) {
  const std::string text = longScript(3000);
  const Script header = checkScript(text, "long.gls");
  struct Stop {};
  std::size_t seen = 0;
  EXPECT_THROW(streamScriptAhead(text, header,
                                 [&](ScriptCommand&&) {
                                   if (++seen == 10) throw Stop{};
                                 }),
               Stop);
  EXPECT_EQ(seen, 10u);

  // Unchecked text with an error on line 9000: every command before it
  // reaches the sink, then the error is thrown as streamScript throws it.
  std::string bad = longScript(2000);
  std::size_t lines = 0, cut = 0;
  for (std::size_t i = 0; i < bad.size() && lines < 8999; ++i)
    if (bad[i] == '\n') ++lines, cut = i + 1;
  bad = bad.substr(0, cut) + "glVertex3f 0 0 nope\n" + bad.substr(cut);
  Script badHeader;
  badHeader.file = "bad.gls";
  badHeader.width = badHeader.height = 16;
  std::vector<int> plainLines, aheadLines;
  std::string plainError, aheadError;
  try {
    streamScript(bad, badHeader, [&](ScriptCommand&& c) { plainLines.push_back(c.line); });
  } catch (const ScriptError& e) {
    plainError = e.what();
  }
  try {
    streamScriptAhead(bad, badHeader, [&](ScriptCommand&& c) { aheadLines.push_back(c.line); });
  } catch (const ScriptError& e) {
    aheadError = e.what();
  }
  EXPECT_EQ(plainError, "bad.gls:9000:16: argument 3 of glVertex3f is a number: expected a C literal, got 'nope'");
  EXPECT_EQ(aheadError, plainError);
  EXPECT_EQ(aheadLines, plainLines);
  EXPECT_GT(aheadLines.size(), 5000u);
}

// The message of the ScriptError `read` throws on `text`, or "".
template <typename Read>
std::string errorOf(const Read& read) {
  try {
    read();
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "";
}
std::string checkError(const std::string& text) {
  return errorOf([&] { checkScript(text, "s.gls"); });
}
std::string headerError(const std::string& text) {
  return errorOf([&] { scanScriptHeader(text, "s.gls"); });
}
// The error `mpr gl` with more than one thread reports: the header's, or
// else the reading's (ahead, on its own thread).
std::string readingError(const std::string& text) {
  const std::string header = headerError(text);
  if (!header.empty()) return header;
  return errorOf([&] { streamScriptAhead(text, scanScriptHeader(text, "s.gls"), [](ScriptCommand&&) {}); });
}

// streamScript with a call sink: every call reaches it as its parts (none
// as a command), the directives the command sink, together streamScript's
// commands in its order; a call line repeated comes from the lines kept
// by their bytes, so the long script's repeats are covered too. Once a
// streamed probe falls outside the window, nothing more reaches either
// sink, and the error is the one streamScript alone throws.
TEST(ScriptStream, ACallSinkGetsEachCallAsItsPartsInTheCommandsOrder) {
  const NamedScripts scripts = withRepositoryScripts(
      {{"long.gls", longScript(3000)},
       // (The comment at the end: the line kept for its bytes is found only
       // with 64 bytes after it.)
       {"outside.gls", "@framebuffer 8 8\nglFinish\nglFinish\n@expect stencil 300 0 1\nglFinish\n@pass p\nglFlush\n# " +
                           std::string(70, 'c') + "\n"}},
      {"tests/conformance", "tests/probes/pass", "scenes"});
  for (const auto& named : scripts) {
    // (Names, not a structured binding: clang 14's C++20 captures none in a lambda.)
    const std::string& path = named.first;
    const std::string& text = named.second;
    const Script header = scanScriptHeader(text, path);
    std::vector<ScriptCommand> plain, parts;
    const std::string plainError = errorOf([&] { streamScript(text, header, [&](ScriptCommand&& c) { plain.push_back(c); }); });
    std::size_t callsAsCommands = 0;
    ScriptText whole = ScriptText::ofString(text);
    const std::string partsError = errorOf([&] {
      streamScript(
          whole, header,
          [&](ScriptCommand&& c) {
            callsAsCommands += c.kind == ScriptCommand::Kind::Call;
            parts.push_back(std::move(c));
          },
          [&](GLCall call, int line, std::span<const ScriptArg> args) {
            ScriptCommand c;
            c.line = line;
            c.call = call;
            c.args.assign(args.begin(), args.end());
            parts.push_back(std::move(c));
          });
    });
    EXPECT_EQ(partsError, plainError) << path;
    EXPECT_EQ(callsAsCommands, 0u) << path;
    ASSERT_EQ(parts.size(), plain.size()) << path;
    for (std::size_t i = 0; i < plain.size(); ++i)
      expectSameCommand(parts[i], plain[i], path + " command " + std::to_string(i));
    if (path == "outside.gls") {
      EXPECT_FALSE(plainError.empty());
      EXPECT_EQ(plain.size(), 2u);  // the two calls before the probe
    }
  }
}

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
    EXPECT_EQ(readingError(text), checkError(text)) << text;
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

// One seeded edit of a script's lines: a line dropped, doubled, moved or
// cut short, a character changed, or a line of another kind put in.
std::string mutated(const std::string& text, std::mt19937& rng) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % std::max<std::size_t>(n, 1)); };
  static const char* const kInserted[] = {"@framebuffer 8 8", "@profile mesa", "@expect stencil 300 0 1",
                                          "@expect stencil 0 0 1 2", "@expect-picture stencil 0 0", "@end",
                                          "@snapshot final", "@pass", "glBegin GL_QUADS", "glEnd",
                                          "glVertex3f 0 0", "glFoo 1", "1 1 1", "glStencilFunc GL_LESS 1 0x1FF"};
  const std::size_t i = pick(lines.size());
  switch (rng() % 6) {
    case 0: lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i)); break;
    case 1: lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), lines[i]); break;
    case 2: std::swap(lines[i], lines[pick(lines.size())]); break;
    case 3: lines[i] = lines[i].substr(0, pick(lines[i].size() + 1)); break;
    case 4:
      if (!lines[i].empty()) lines[i][pick(lines[i].size())] = " x9.-|@#e\t"[rng() % 11];
      break;
    default: lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), kInserted[pick(std::size(kInserted))]);
  }
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k) out += lines[k] + (k + 1 < lines.size() ? "\n" : "");
  return out;
}

TEST(ScriptStream, TheReadingFromTheHeaderThrowsCheckScriptsError) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  std::vector<std::string> scripts;
  for (const char* folder : {"tests/conformance", "tests/conformance/repro", "tests/probes/pass", "tests/probes/fail"})
    for (const auto& entry : std::filesystem::directory_iterator(root / folder))
      if (entry.path().extension() == ".gls") scripts.push_back(readScriptText(entry.path().string()));
  std::mt19937 rng(20261204);
  int broken = 0, total = 0;
  for (const std::string& original : scripts)
    for (int k = 0; k < 25; ++k) {
      std::string text = original;
      for (int edits = 1 + static_cast<int>(rng() % 3); edits > 0; --edits) text = mutated(text, rng);
      const std::string expected = checkError(text);
      ASSERT_EQ(readingError(text), expected) << text;
      broken += !expected.empty();
      ++total;
    }
  // Both kinds, many of each.
  EXPECT_GT(broken, total / 4);
  EXPECT_LT(broken, total);
}

}  // namespace
}  // namespace mpr

namespace mpr {
namespace {

constexpr std::size_t kPieceSizes[] = {1, 5, 64, 1000};

// The error of each pass `mpr gl` makes, read in pieces.
std::string checkErrorInPieces(const std::string& text, std::size_t pieceBytes) {
  return errorOf([&] {
    ScriptText pieces = ScriptText::ofString(text, pieceBytes);
    checkScript(pieces, "s.gls");
  });
}
std::string readingErrorInPieces(const std::string& text, std::size_t pieceBytes) {
  return errorOf([&] {
    ScriptText pieces = ScriptText::ofString(text, pieceBytes);
    const Script header = scanScriptHeader(pieces, "s.gls");
    streamScriptAhead(pieces, header, [](ScriptCommand&&) {});
  });
}

TEST(ScriptText, EveryScriptReadInPiecesIsItsWholeText) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  const testing::TempFolder folder("mpr-script-text");
  const std::filesystem::path& temp = folder.path;
  int scripts = 0;
  for (const char* folder : {"tests/conformance", "tests/conformance/repro", "tests/probes/pass", "tests/probes/fail"})
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      if (entry.path().extension() != ".gls") continue;
      const std::string path = entry.path().string();
      const std::string text = readScriptText(path);
      const Script stored = parseScript(text, path);
      // The same text with CRLF line ends and no '\n' at the end: lines cut
      // across pieces either way.
      std::string crlf;
      for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
      while (!crlf.empty() && (crlf.back() == '\n' || crlf.back() == '\r')) crlf.pop_back();
      for (const std::string* variant : std::array<const std::string*, 2>{&text, &crlf}) {
        for (std::size_t pieceBytes : kPieceSizes) {
          const std::string where = path + " in pieces of " + std::to_string(pieceBytes);
          ScriptText pieces = ScriptText::ofString(*variant, pieceBytes);
          const Script header = checkScript(pieces, path);
          EXPECT_EQ(header.width, stored.width) << where;
          EXPECT_EQ(header.height, stored.height) << where;
          EXPECT_EQ(header.profile, stored.profile) << where;
          std::vector<ScriptCommand> streamed;
          streamScript(pieces, header, [&](ScriptCommand&& c) { streamed.push_back(std::move(c)); });
          ASSERT_EQ(streamed.size(), stored.commands.size()) << where;
          for (std::size_t i = 0; i < streamed.size(); ++i)
            expectSameCommand(streamed[i], stored.commands[i], where + " command " + std::to_string(i));
        }
      }
      // From the file, in small pieces, on the reading thread.
      const std::filesystem::path copy = temp / "s.gls";
      std::ofstream(copy, std::ios::binary) << crlf;
      ScriptText file = ScriptText::ofFile(copy.string(), 61);
      const Script header = scanScriptHeader(file, path);
      std::vector<ScriptCommand> ahead;
      streamScriptAhead(file, header, [&](ScriptCommand&& c) { ahead.push_back(std::move(c)); });
      ASSERT_EQ(ahead.size(), stored.commands.size()) << path;
      for (std::size_t i = 0; i < ahead.size(); ++i)
        expectSameCommand(ahead[i], stored.commands[i], path + " from its file, command " + std::to_string(i));
      ++scripts;
    }
  EXPECT_GT(scripts, 50);
}

TEST(ScriptText, ABrokenScriptReadInPiecesFailsAsItsWholeText) {
  const std::filesystem::path root(MPR_SOURCE_DIR);
  std::vector<std::string> scripts;
  for (const char* folder : {"tests/conformance", "tests/probes/pass"})
    for (const auto& entry : std::filesystem::directory_iterator(root / folder))
      if (entry.path().extension() == ".gls") scripts.push_back(readScriptText(entry.path().string()));
  std::mt19937 rng(20261205);
  int broken = 0, total = 0;
  for (const std::string& original : scripts)
    for (int k = 0; k < 6; ++k) {
      std::string text = original;
      for (int edits = 1 + static_cast<int>(rng() % 3); edits > 0; --edits) text = mutated(text, rng);
      const std::string expected = checkError(text);
      for (std::size_t pieceBytes : kPieceSizes) {
        ASSERT_EQ(checkErrorInPieces(text, pieceBytes), expected) << "pieces of " << pieceBytes << ":\n" << text;
        ASSERT_EQ(readingErrorInPieces(text, pieceBytes), expected) << "pieces of " << pieceBytes << ":\n" << text;
      }
      broken += !expected.empty();
      ++total;
    }
  EXPECT_GT(broken, total / 4);
  EXPECT_LT(broken, total);
}

TEST(ScriptText, AnUnreadableFileIsAScriptErrorAsReadScriptTextsIs) {
  for (const std::string& path : {std::string("/nonexistent/s.gls"), std::string("/tmp"), std::string("/dev/zero")}) {
    const std::string expected = errorOf([&] { readScriptText(path); });
    ASSERT_FALSE(expected.empty()) << path;
    EXPECT_EQ(errorOf([&] { ScriptText::ofFile(path); }), expected) << path;
  }
}

}  // namespace
}  // namespace mpr
