#include "script/gl_script.hpp"

#include "util/input_file.hpp"

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_map>

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_enums.hpp"
#include "script/call_set.hpp"
#include "script/probe_directives.hpp"
#include "script/script_line.hpp"
#include "script/recent_decimals.hpp"
#include "script/recent_lines.hpp"
#include "script/short_decimal.hpp"
#include "script/script_text.hpp"
#include "util/check.hpp"
#include "util/spelling.hpp"

namespace mpr {
namespace {


using Token = ScriptToken;

class Parser {
 public:
  // How parse hands commands on: Store keeps them in the Script; Check keeps
  // none (a first pass that finds every error); Stream hands each to the
  // sink as soon as it is complete, probes placed in the window `streamSize`
  // that the Check pass found; Header checks as Check does up to the first
  // call and returns there (the window and profile, which come before it).
  enum class Mode { Store, Check, Stream, Header };
  using Sink = std::function<void(ScriptCommand&&)>;

  Parser(const std::string& file) : file_(file) {}
  Parser(const std::string& file, Mode mode, Sink sink = {}, int streamWidth = 0, int streamHeight = 0,
         ScriptCallSink callSink = {})
      : file_(file),
        mode_(mode),
        sink_(std::move(sink)),
        callSink_(std::move(callSink)),
        streamWidth_(streamWidth),
        streamHeight_(streamHeight) {}

  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw ScriptError(file_, line, column, message);
  }

  std::optional<double> parseNumber(std::string_view t) const {
    // A plain decimal ([-]digits[.digits][e[-]digits]) through from_chars:
    // correctly rounded, as strtod is, so the same double; anything else
    // (a sign '+', hex, a suffix, inf, out of range) takes strtod's path.
    const bool plain = !t.empty() && t[0] != '+' && t.find_first_not_of("0123456789.-+eE") == std::string_view::npos;
    if (plain) {
      double v = 0.0;
      const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v, std::chars_format::general);
      if (ec == std::errc() && end == t.data() + t.size()) return v;
    }
    std::string s(t);
    if (!s.empty() && (s.back() == 'f' || s.back() == 'F') && s.find_first_of("0123456789") != std::string::npos &&
        s.rfind("0x", 0) != 0 && s.rfind("-0x", 0) != 0 && s.rfind("+0x", 0) != 0)
      s.pop_back();  // C float suffix
    if (s.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return v;
  }

  // Parses `tok` into `a`, every field written: a call line's arguments are
  // parsed into the ones the line before left (their count kept), not built,
  // moved and destroyed an argument at a time (a fifth of the line loop).
  void parseArg(char kind, const Token& tok, int line, std::string_view callName, int index, ScriptArg& a) const {
    // A primitive mode parses as an enum, an enum-or-integer as an integer
    // (the distinction only names values when a trace is written).
    if (kind == 'p') kind = 'e';
    if (kind == 'n') kind = 'i';
    a.number = 0.0;
    a.bits = 0;
    a.column = tok.column;  // messages quote the token itself
    const std::string_view text = tok.text;
    // Built only for a message: an argument that parses costs no string.
    const auto where = [&] { return "argument " + std::to_string(index + 1) + " of " + std::string(callName); };
    const bool isName = tok.text.rfind("GL_", 0) == 0;
    if (isName && kind != 'b') {
      const auto v = glEnumValue(tok.text);
      if (!v) fail(line, tok.column, "unknown GL enumerant '" + std::string(text) + "' (" + where() + ")");
      if (kind == 'z' && *v != GL_TRUE && *v != GL_FALSE)
        fail(line, tok.column, where() + " is a boolean: GL_TRUE or GL_FALSE, not " + std::string(text));
      if (kind == 'u') fail(line, tok.column, where() + " is an unsigned byte (0..255), not " + std::string(text));
      a.bits = *v;
      a.number = *v;
      return;
    }
    switch (kind) {
      case 'e':
        fail(line, tok.column, where() + " is an enum: expected a GL_ name, got '" + std::string(text) + "'");
      case 'b': {
        std::uint32_t bits = 0;
        if (!isName) {
          const auto n = parseScriptInteger(tok.text);
          if (!n || *n < 0 || *n > 0xFFFFFFFFLL)
            fail(line, tok.column, where() + " is a bitfield: GL names joined by '|', got '" + std::string(text) + "'");
          bits = static_cast<std::uint32_t>(*n);
        } else {
          size_t start = 0;
          while (start <= tok.text.size()) {
            const size_t bar = tok.text.find('|', start);
            const std::string_view part = tok.text.substr(start, bar == std::string_view::npos ? std::string_view::npos : bar - start);
            const auto v = glEnumValue(part);
            if (!v)
              fail(line, tok.column + static_cast<int>(start),
                   "unknown GL enumerant '" + std::string(part) + "' in bitfield (" + where() + ")");
            bits |= *v;
            if (bar == std::string_view::npos) break;
            start = bar + 1;
          }
        }
        a.bits = bits;
        a.number = bits;
        return;
      }
      case 'i':
      case 'u':
      case 'z': {
        const auto n = parseScriptInteger(tok.text);
        if (!n) fail(line, tok.column, where() + " is an integer: expected a decimal or 0x literal, got '" + std::string(text) + "'");
        if (kind == 'u' && (*n < 0 || *n > 255))
          fail(line, tok.column, where() + " is an unsigned byte: " + std::string(text) + " is outside 0..255");
        if (kind == 'z' && *n != 0 && *n != 1)
          fail(line, tok.column, where() + " is a boolean: GL_TRUE or GL_FALSE, not " + std::string(text));
        if (*n < -2147483648LL || *n > 4294967295LL)
          fail(line, tok.column, where() + ": " + std::string(text) + " does not fit in 32 bits");
        a.bits = static_cast<std::uint32_t>(*n);
        a.number = static_cast<double>(*n);
        return;
      }
      default: {  // f, m, v
        // A short plain decimal was read by parseNumberArg before this.
        const auto v = parseNumber(tok.text);
        if (!v) fail(line, tok.column, where() + " is a number: expected a C literal, got '" + std::string(text) + "'");
        a.number = *v;
        return;
      }
    }
  }

  // A number argument ('f'): a short plain decimal (most of a trace's
  // numbers) read in line, anything else (a GL_ name, an error) by parseArg.
  void parseNumberArg(const Token& tok, std::string_view callName, int index, ScriptArg& a) const {
    if (recentDecimals_.read(tok.text, pieceEnd_, a.number)) {
      a.bits = 0;
      a.column = tok.column;
      return;
    }
    parseArg('f', tok, lineNo_, callName, index, a);
  }

  // The whole text, read from its start a piece at a time (a parser parses once).
  Script parse(ScriptText& text) {
    text.rewind();
    script_.file = file_;
    std::string_view piece;
    bool last = false;
    while (text.next(piece, last))
      if (parseLines(piece, last)) return std::move(script_);  // the header's end
    return finish();
  }

  // The lines of one piece of the text, in the state the pieces before
  // left (the line number, the directives seen, an open @expect-picture);
  // a piece that is not the last ends in '\n'. True when the parse is over
  // (a header's first call).
  bool parseLines(std::string_view text, bool lastPiece) {
    if (mode_ == Mode::Store) {
      script_.text.append(text);
      // A command a line at most: one allocation for the whole of a text
      // given in one piece, not a growing copy of them all.
      const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
      if (script_.commands.capacity() < script_.commands.size() + lines)
        script_.commands.reserve(std::max(script_.commands.size() + lines, 2 * script_.commands.capacity()));
    }
    pieceEnd_ = text.data() + text.size();
    size_t pos = 0;
    // A piece before the last ends in '\n': no line starts at its end.
    while (lastPiece ? pos <= text.size() : pos < text.size()) {
      // A call line parsed before: its command again, unparsed (a call's
      // parse depends on its bytes alone once the header is read).
      if constexpr (kCheckCaches) MPR_CHECK(!checkedLine_);  // the line checked last reached keep() below
      if (mode_ != Mode::Header && !picture_) {
        const RecentLines::Entry* kept = recentLines_.find(text, pos);
        if (kCheckCaches && kept) {
          checkedLine_ = *kept;  // parsed all the same below, and compared
          kept = nullptr;
        }
        if (kept) {
          pos += kept->size + 1;
          ++lineNo_;
          if (callSink_) {  // its parts as kept: no command made
            noteBlock(kept->call);
            if (!outsideProbe_) callSink_(kept->call, lineNo_, std::span<const ScriptArg>(kept->args, kept->argCount));
            continue;
          }
          ScriptCommand& cmd = startCall(kept->call);
          cmd.args.assign(kept->args, kept->args + kept->argCount);
          emitCall(cmd);
          continue;
        }
      }
      const ScriptLine cut = nextScriptLine(text, pos, tokens_);
      const std::string_view line = cut.text;
      pos = cut.next;
      ++lineNo_;
      const std::vector<Token>& toks = tokens_;
      if (toks.empty()) {
        if (cut.last) break;
        continue;
      }
      const Token& head = toks[0];
      if (picture_) {
        if (head.text == "@end") {
          if (toks.size() != 1) fail(lineNo_, toks[1].column, "@end takes nothing");
          if (picture_->probe->cells.empty()) fail(lineNo_, head.column, "@expect-picture has no rows before @end");
          finishPicture(*picture_);
          if (mode_ == Mode::Stream) {
            placeStreamedProbe(*picture_);
            pictureCommand_.probe = std::move(picture_->probe);
            emit(script_, std::move(pictureCommand_));
          } else {
            probes_.push_back(std::move(*picture_));
          }
          picture_.reset();
        } else {
          addPictureRow(file_, *picture_, toks, lineNo_);
        }
        continue;
      }
      // Directives start with '@' (a call line, most of a script, skips
      // their comparisons).
      if (head.text[0] == '@' && (head.text == "@expect" || head.text == "@expect-picture")) {
        if (inBegin_) fail(lineNo_, head.column, std::string(head.text) + " between glBegin and glEnd");
        PendingProbe pp = head.text == "@expect" ? parseExpect(file_, toks, lineNo_) : parseExpectPicture(file_, toks, lineNo_);
        pp.command = script_.commands.size();
        ScriptCommand cmd;
        cmd.kind = ScriptCommand::Kind::Probe;
        cmd.line = lineNo_;
        cmd.label = std::string(line.substr(static_cast<size_t>(head.column - 1),
                                            static_cast<size_t>(toks.back().column - head.column) + toks.back().text.size()));
        if (mode_ == Mode::Stream && head.text == "@expect") {
          placeStreamedProbe(pp);
          cmd.probe = std::move(pp.probe);
          emit(script_, std::move(cmd));
          continue;
        }
        if (mode_ == Mode::Stream) pictureCommand_ = std::move(cmd);  // handed on at its @end
        else emit(script_, std::move(cmd));
        if (head.text == "@expect") probes_.push_back(std::move(pp));
        else picture_ = std::move(pp);
        continue;
      }
      if (head.text[0] == '@') {
        if (head.text == "@end") fail(lineNo_, head.column, "@end without @expect-picture");
        ScriptCommand cmd;
        cmd.line = lineNo_;
        if (head.text == "@framebuffer") {
          if (sawCall_) fail(lineNo_, head.column, "@framebuffer must come before the first call");
          if (sawFramebuffer_) fail(lineNo_, head.column, "@framebuffer given twice");
          if (toks.size() != 3) fail(lineNo_, head.column, "@framebuffer takes a width and a height");
          const auto w = parseScriptInteger(toks[1].text), h = parseScriptInteger(toks[2].text);
          if (!w) fail(lineNo_, toks[1].column, "framebuffer width must be an integer");
          if (!h) fail(lineNo_, toks[2].column, "framebuffer height must be an integer");
          const std::string why = Framebuffer::checkSize(*w, *h);
          if (!why.empty()) fail(lineNo_, toks[1].column, why);
          script_.width = static_cast<int>(*w);
          script_.height = static_cast<int>(*h);
          sawFramebuffer_ = true;
          continue;
        }
        if (head.text == "@profile") {
          if (sawCall_) fail(lineNo_, head.column, "@profile must come before the first call");
          if (sawProfile_) fail(lineNo_, head.column, "@profile given twice");
          if (toks.size() != 2) fail(lineNo_, head.column, "@profile takes one profile name");
          if (!findProfile(toks[1].text)) {
            std::string names;
            for (const auto& n : profileNames()) names += (names.empty() ? "" : ", ") + n;
            fail(lineNo_, toks[1].column, "unknown profile '" + std::string(toks[1].text) + "' (known: " + names + ")");
          }
          script_.profile = std::string(toks[1].text);
          sawProfile_ = true;
          continue;
        }
        if (head.text == "@pass") {
          if (toks.size() < 2) fail(lineNo_, head.column, "@pass needs a label");
          cmd.kind = ScriptCommand::Kind::Pass;
          // The label is the rest of the line, comments excluded.
          const size_t from = static_cast<size_t>(toks[1].column - 1);
          const Token& last = toks.back();
          cmd.label = std::string(line.substr(from, static_cast<size_t>(last.column - 1) + last.text.size() - from));
          emit(script_, std::move(cmd));
          continue;
        }
        if (head.text == "@snapshot") {
          if (toks.size() != 2) fail(lineNo_, head.column, "@snapshot takes one name");
          const std::string name(toks[1].text);
          const bool ok = std::all_of(name.begin(), name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
          }) && name[0] != '.';
          if (!ok) fail(lineNo_, toks[1].column, "snapshot name '" + name + "' may use letters, digits, '_', '-' and '.'");
          if (!snapshots_.insert(name).second) fail(lineNo_, toks[1].column, "snapshot '" + name + "' is taken twice");
          cmd.kind = ScriptCommand::Kind::Snapshot;
          cmd.label = name;
          emit(script_, std::move(cmd));
          continue;
        }
        if (head.text == "@window_map") {
          // docs/reference/gl-script-directives.md: 9 numbers (column by column) or off.
          cmd.kind = ScriptCommand::Kind::WindowMap;
          if (toks.size() == 2 && toks[1].text == "off") {
            emit(script_, std::move(cmd));
            continue;
          }
          if (toks.size() != 10)
            fail(lineNo_, head.column, "@window_map takes 9 numbers (a 3x3 matrix, column by column) or off");
          cmd.args.resize(9);
          for (std::size_t t = 1; t < toks.size(); ++t)
            parseNumberArg(toks[t], "@window_map", static_cast<int>(t - 1), cmd.args[t - 1]);
          emit(script_, std::move(cmd));
          continue;
        }
        if (head.text == "@count_fragments") {
          if (toks.size() != 2 || (toks[1].text != "begin" && toks[1].text != "end"))
            fail(lineNo_, head.column, "@count_fragments takes begin or end");
          const bool begin = toks[1].text == "begin";
          if (begin == counting_) fail(lineNo_, toks[1].column, begin ? "@count_fragments begin twice without end"
                                                                    : "@count_fragments end without begin");
          counting_ = begin;
          cmd.kind = ScriptCommand::Kind::FragmentCount;
          cmd.label = std::string(toks[1].text);
          emit(script_, std::move(cmd));
          continue;
        }
        fail(lineNo_, head.column, "unknown directive '" + std::string(head.text) +
                                      "' (known: @framebuffer, @profile, @pass, @snapshot, @window_map, "
                                      "@count_fragments, @expect, @expect-picture)");
      }

      if (mode_ == Mode::Header) return true;
      // A script_ repeats a few calls (glNormal3f, glVertex3f, ...): the last
      // few are tried before the table.
      const CallSpec* spec = nullptr;
      for (const CallSpec* recent : recentCalls_)
        if (recent && sameName(recent->name, head.text)) {
          spec = recent;
          break;
        }
      if (!spec && (spec = findCall(head.text)))
        recentCalls_[nextRecent_++ % recentCalls_.size()] = spec;
      if (!spec) {
        const std::string near = closestCallName(head.text);
        fail(lineNo_, head.column, "'" + std::string(head.text) + "' is not a call of the GL script call set" +
                                      (near.empty() ? "" : "; did you mean '" + near + "'?"));
      }
      sawCall_ = true;
      // One command object for every call line (startCall).
      ScriptCommand& cmd = startCall(spec->call);
      const std::string_view kinds = spec->args;
      const size_t given = toks.size() - 1;
      const bool variadic = !kinds.empty() && kinds.back() == 'v';
      const size_t fixed = variadic ? kinds.size() - 1 : kinds.size();
      size_t expected = fixed;
      for (char k : kinds) if (k == 'm') expected += 15;
      const int endColumn = static_cast<int>(line.size()) + 1;
      if (!variadic && given != expected) {
        const int col = given > expected ? toks[expected + 1].column : endColumn;
        fail(lineNo_, col, std::string(spec->name) + " takes " + std::to_string(expected) + " argument" +
                              (expected == 1 ? "" : "s") + ", got " + std::to_string(given));
      }
      if (variadic && given < fixed + 1)
        fail(lineNo_, endColumn, std::string(spec->name) + " takes " + std::to_string(fixed) +
                                    " argument(s) and then its values, got " + std::to_string(given) + " argument(s)");
      // Token t is argument t - 1: every token is one once the counts hold.
      cmd.args.resize(given);
      size_t t = 1;
      for (size_t k = 0; k < kinds.size(); ++k) {
        const char kind = kinds[k];
        if (kind == 'm') {
          for (int j = 0; j < 16; ++j, ++t) parseNumberArg(toks[t], spec->name, static_cast<int>(t - 1), cmd.args[t - 1]);
        } else if (kind == 'v') {
          const int want = glVectorCount(spec->call, cmd.args[t - 2].bits);
          const size_t have = toks.size() - t;
          if (want > 0 && have != static_cast<size_t>(want))
            fail(lineNo_, have > static_cast<size_t>(want) ? toks[t + want].column : endColumn,
                 std::string(spec->name) + " " + std::string(toks[t - 1].text) + " takes " + std::to_string(want) +
                     " value" + (want == 1 ? "" : "s") + ", got " + std::to_string(have));
          if (want == 0 && have > 4) fail(lineNo_, toks[t + 4].column, std::string(spec->name) + " takes at most 4 values");
          for (; t < toks.size(); ++t) parseNumberArg(toks[t], spec->name, static_cast<int>(t - 1), cmd.args[t - 1]);
        } else if (kind == 'f') {
          parseNumberArg(toks[t], spec->name, static_cast<int>(t - 1), cmd.args[t - 1]);
          ++t;
        } else {
          parseArg(kind, toks[t], lineNo_, spec->name, static_cast<int>(t - 1), cmd.args[t - 1]);
          ++t;
        }
      }
      checkCallSet(file_, *spec, cmd, toks, lineNo_);
      recentLines_.keep(cmd.call, cmd.args);
      if constexpr (kCheckCaches) checkKeptLine(cmd);
      emitCall(cmd);
    }
    return false;
  }

  // The cache-check build: a line RecentLines gave back, parsed again, is
  // the same call with the same arguments, bit for bit.
  void checkKeptLine(const ScriptCommand& cmd) {
    if (!checkedLine_) return;
    const RecentLines::Entry& kept = *checkedLine_;
    MPR_CHECK(kept.call == cmd.call);
    MPR_CHECK_EQ(std::size_t{kept.argCount}, cmd.args.size());
    for (std::size_t i = 0; i < cmd.args.size(); ++i) {
      MPR_CHECK(std::memcmp(&kept.args[i].number, &cmd.args[i].number, sizeof(double)) == 0);
      MPR_CHECK_EQ(kept.args[i].bits, cmd.args[i].bits);
      MPR_CHECK_EQ(kept.args[i].column, cmd.args[i].column);
    }
    checkedLine_.reset();
  }

  // After the last piece: what only the whole script settles.
  Script finish() {
    if constexpr (kCheckCaches) MPR_CHECK(!checkedLine_);
    if (picture_) fail(picture_->line, picture_->column, "@expect-picture without @end");
    if (outsideProbe_) throw *outsideProbe_;
    for (PendingProbe& pp : probes_) {
      placeProbe(file_, pp, script_.width, script_.height);
      if (mode_ == Mode::Store) script_.commands[pp.command].probe = std::move(pp.probe);
    }
    return std::move(script_);
  }


 private:
  // The command of the current call line, reset for `call` (its argument
  // vector keeps its capacity unless a sink moved it away).
  ScriptCommand& startCall(GLCall call) {
    ScriptCommand& cmd = callCommand_;
    cmd.kind = ScriptCommand::Kind::Call;
    cmd.label.clear();
    cmd.probe.reset();
    cmd.line = lineNo_;
    cmd.call = call;
    return cmd;
  }

  // A call line's command handed on; glBegin and glEnd open and close the
  // block an @expect may not stand in.
  void emitCall(ScriptCommand& cmd) {
    noteBlock(cmd.call);
    if (callSink_) {
      if (!outsideProbe_) callSink_(cmd.call, cmd.line, cmd.args);
      return;
    }
    emit(script_, std::move(cmd));
  }
  void noteBlock(GLCall call) {
    if (call == GLCall::Begin) inBegin_ = true;
    if (call == GLCall::End) inBegin_ = false;
  }

  void emit(Script& script, ScriptCommand&& cmd) const {
    if (mode_ == Mode::Store) script.commands.push_back(std::move(cmd));
    else if (mode_ == Mode::Stream && !outsideProbe_) sink_(std::move(cmd));
  }

  // A streamed probe is placed where it stands, in the window the header
  // gave. One outside the window is the script's error only when no other
  // error follows it, since the other modes place their probes at the end
  // (the window is known only then): the stream keeps the error, hands
  // nothing more on, and reads on to the end, which throws it.
  void placeStreamedProbe(PendingProbe& pp) {
    if (outsideProbe_) return;
    try {
      placeProbe(file_, pp, streamWidth_, streamHeight_);
    } catch (const ScriptError& e) {
      outsideProbe_ = e;
    }
  }

  std::string file_;
  std::optional<ScriptError> outsideProbe_;  // a streamed probe's, thrown at the end (placeStreamedProbe)
  std::vector<Token> tokens_;          // the current line's
  ScriptCommand callCommand_;          // the current call line's (kind Call, no label or probe)
  std::array<const CallSpec*, 4> recentCalls_{};  // the last calls' entries
  std::size_t nextRecent_ = 0;
  const char* pieceEnd_ = nullptr;  // the end of the piece parseLines reads (shortDecimalAt's limit)
  mutable RecentDecimals recentDecimals_;  // the numbers read last, by their bytes
  RecentLines recentLines_;                // the call lines parsed last, by their bytes
  std::optional<RecentLines::Entry> checkedLine_;  // the cache-check build's kept line, being parsed
  Mode mode_ = Mode::Store;
  Sink sink_;
  ScriptCallSink callSink_;  // Stream: the calls as their parts (sink_ the rest), when set
  int streamWidth_ = 0, streamHeight_ = 0;
  // What the lines read so far left (parseLines).
  Script script_;
  bool sawCall_ = false, sawFramebuffer_ = false, sawProfile_ = false, counting_ = false, inBegin_ = false;
  std::set<std::string> snapshots_;
  std::vector<PendingProbe> probes_;    // placed in the window once the whole script is read
  std::optional<PendingProbe> picture_; // an @expect-picture awaiting its @end
  ScriptCommand pictureCommand_;        // its command, held back until @end when streaming
  int lineNo_ = 0;
};

}  // namespace

std::size_t Script::callCount() const {
  return static_cast<std::size_t>(std::count_if(commands.begin(), commands.end(), [](const ScriptCommand& c) {
    return c.kind == ScriptCommand::Kind::Call;
  }));
}

// The number of values a `...v` call takes for its pname, or 0 when the pname
// is not one the function takes (GL will reject it; any 1..4 values parse).

std::size_t Script::probeCount() const {
  return static_cast<std::size_t>(std::count_if(commands.begin(), commands.end(), [](const ScriptCommand& c) {
    return c.kind == ScriptCommand::Kind::Probe;
  }));
}

Script parseScript(std::string_view text, const std::string& file) {
  ScriptText whole = ScriptText::ofString(text);
  return Parser(file).parse(whole);
}

Script checkScript(ScriptText& text, const std::string& file) { return Parser(file, Parser::Mode::Check).parse(text); }

Script checkScript(std::string_view text, const std::string& file) {
  ScriptText whole = ScriptText::ofString(text);
  return checkScript(whole, file);
}

Script scanScriptHeader(ScriptText& text, const std::string& file) {
  return Parser(file, Parser::Mode::Header).parse(text);
}

Script scanScriptHeader(std::string_view text, const std::string& file) {
  ScriptText whole = ScriptText::ofString(text);
  return scanScriptHeader(whole, file);
}

void streamScript(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink) {
  Parser(header.file, Parser::Mode::Stream, sink, header.width, header.height).parse(text);
}

void streamScript(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink,
                  const ScriptCallSink& call) {
  Parser(header.file, Parser::Mode::Stream, sink, header.width, header.height, call).parse(text);
}

void streamScript(std::string_view text, const Script& header, const std::function<void(ScriptCommand&&)>& sink) {
  ScriptText whole = ScriptText::ofString(text);
  streamScript(whole, header, sink);
}

std::string readScriptText(const std::string& path) {
  try {
    return readInputFile(path, kMaxScriptBytes, "the script");
  } catch (const std::runtime_error& e) {
    throw ScriptError(path, 0, 0, e.what());
  }
}

Script loadScript(const std::string& path) { return parseScript(readScriptText(path), path); }

}  // namespace mpr
