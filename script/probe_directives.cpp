// The probe directives of a GL script: @expect and @expect-picture read into
// ScriptProbes (docs: the GL script directives), placed in the window once
// its size is known.
#include "script/probe_directives.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <string>

#include "script/gl_script.hpp"

namespace mpr {
namespace {

[[noreturn]] void fail(const std::string& file, int line, int column, const std::string& message) {
  throw ScriptError(file, line, column, message);
}

long long integerArg(const std::string& file, const std::vector<ScriptToken>& toks, std::size_t i, int line,
                     const std::string& what, long long lo, long long hi) {
  const auto n = parseScriptInteger(toks[i].text);
  if (!n) fail(file, line, toks[i].column, what + " must be an integer, not '" + std::string(toks[i].text) + "'");
  if (*n < lo || *n > hi)
    fail(file, line, toks[i].column, what + " " + std::string(toks[i].text) + " is outside " + std::to_string(lo) + ".." +
                                   std::to_string(hi));
  return *n;
}

}  // namespace

std::optional<long long> parseScriptInteger(std::string_view t) {
  std::string s(t);
  if (s.empty()) return std::nullopt;
  size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  int base = 10;
  if (s.size() > i + 1 && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X')) base = 16;
  if (i >= s.size()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, base);
  if (end != s.c_str() + s.size() || errno == ERANGE) return std::nullopt;
  if (base == 16 && s.size() <= i + 2) return std::nullopt;
  return v;
}

// @expect BUFFER X Y VALUE... | BUFFER all VALUE... | BUFFER rect X Y W H VALUE...
PendingProbe parseExpect(const std::string& file, const std::vector<ScriptToken>& toks, int line) {
  PendingProbe pp{std::make_shared<ScriptProbe>(), 0, line, toks[0].column, 0};
  ScriptProbe& p = *pp.probe;
  static constexpr std::string_view kUsage =
      "@expect takes stencil|depth|color|accum, then X Y, all, or rect X Y W H, then the value";
  if (toks.size() < 2) fail(file, line, toks[0].column, std::string(kUsage));
  const std::string_view buffer = toks[1].text;
  std::size_t values = 1;
  long long lo = 0, hi = 255;
  if (buffer == "stencil") {
    p.buffer = ScriptProbe::Buffer::Stencil;
  } else if (buffer == "depth") {
    p.buffer = ScriptProbe::Buffer::Depth;
    hi = (1 << 24) - 1;
  } else if (buffer == "color") {
    p.buffer = ScriptProbe::Buffer::Color;
    values = 4;
  } else if (buffer == "accum") {
    p.buffer = ScriptProbe::Buffer::Accum;
    values = 4;
    lo = -32768;
    hi = 32767;
  } else {
    fail(file, line, toks[1].column, "unknown buffer '" + std::string(buffer) + "' (known: stencil, depth, color, accum)");
  }
  std::size_t t = 2;
  const int endColumn = toks.back().column + static_cast<int>(toks.back().text.size());
  auto need = [&](std::size_t n, const char* what) {
    if (toks.size() < t + n) fail(file, line, endColumn, "@expect " + std::string(buffer) + " needs " + what);
  };
  need(1, "X Y, all, or rect X Y W H");
  if (toks[t].text == "all") {
    p.form = ScriptProbe::Form::All;
    ++t;
  } else {
    const bool rect = toks[t].text == "rect";
    if (rect) {
      p.form = ScriptProbe::Form::Rect;
      ++t;
    }
    need(rect ? 4 : 2, rect ? "X Y W H" : "X Y");
    pp.xColumn = toks[t].column;
    const int x = static_cast<int>(integerArg(file, toks, t, line, "X", 0, 1 << 30));
    const int y = static_cast<int>(integerArg(file, toks, t + 1, line, "Y", 0, 1 << 30));
    int w = 1, h = 1;
    if (rect) {
      w = static_cast<int>(integerArg(file, toks, t + 2, line, "W", 1, 1 << 30));
      h = static_cast<int>(integerArg(file, toks, t + 3, line, "H", 1, 1 << 30));
    }
    p.region = {x, y, x + w, y + h};
    t += rect ? 4 : 2;
  }
  const std::size_t given = toks.size() - t;
  const bool tolerance = p.buffer == ScriptProbe::Buffer::Color && given == values + 1;
  if (given != values && !tolerance) {
    const std::string want = values == 1 ? "one value" : p.buffer == ScriptProbe::Buffer::Color
                                                             ? "R G B A (bytes) and an optional tolerance"
                                                             : "four words R G B A";
    fail(file, line, given > values ? toks[t + values + (p.buffer == ScriptProbe::Buffer::Color)].column : endColumn,
         "@expect " + std::string(buffer) + " takes " + want + ", got " + std::to_string(given) + " value(s)");
  }
  for (std::size_t i = 0; i < values; ++i)
    p.expected[i] = integerArg(file, toks, t + i, line, std::string(buffer) + " value", lo, hi);
  if (tolerance) p.tolerance = static_cast<int>(integerArg(file, toks, t + values, line, "the tolerance", 0, 255));
  return pp;
}

// @expect-picture stencil X Y, rows until @end (X Y: the bottom-left pixel).
PendingProbe parseExpectPicture(const std::string& file, const std::vector<ScriptToken>& toks, int line) {
  PendingProbe pp{std::make_shared<ScriptProbe>(), 0, line, toks[0].column, 0};
  if (toks.size() != 4 || toks[1].text != "stencil")
    fail(file, line, toks[0].column, "@expect-picture takes stencil X Y (the picture's bottom-left pixel), then rows up to @end");
  pp.probe->form = ScriptProbe::Form::Picture;
  pp.xColumn = toks[2].column;
  const int x = static_cast<int>(integerArg(file, toks, 2, line, "X", 0, 1 << 30));
  const int y = static_cast<int>(integerArg(file, toks, 3, line, "Y", 0, 1 << 30));
  pp.probe->region = {x, y, x, y};
  return pp;
}

// One row of the picture: `.` for 0, `*` for any value, or a decimal 0..255.
void addPictureRow(const std::string& file, PendingProbe& pp, const std::vector<ScriptToken>& toks, int line) {
  ScriptProbe& p = *pp.probe;
  std::vector<int> row;
  std::string text;
  for (const ScriptToken& tok : toks) {
    int v = -1;
    if (tok.text == ".") {
      v = 0;
    } else if (tok.text != "*") {
      const bool digits = !tok.text.empty() && tok.text.size() <= 3 &&
                          std::all_of(tok.text.begin(), tok.text.end(), [](char c) { return c >= '0' && c <= '9'; });
      v = digits ? std::stoi(std::string(tok.text)) : 256;
      if (v > 255)
        fail(file, line, tok.column, "picture cell '" + std::string(tok.text) + "' is not a stencil value 0..255, '.' or '*'" +
                                   (tok.text[0] == '@' ? " (is @end missing?)" : ""));
    }
    row.push_back(v);
    if (!text.empty()) text += ' ';
    text += tok.text;
  }
  if (!p.cells.empty() && row.size() != p.cells[0].size())
    fail(file, line, toks[0].column, "picture row has " + std::to_string(row.size()) + " cells, the first row has " +
                                   std::to_string(p.cells[0].size()));
  p.cells.push_back(std::move(row));
  p.picture += text + "\n";
}

void finishPicture(PendingProbe& pp) {
  ScriptProbe& p = *pp.probe;
  p.region.x1 = p.region.x0 + static_cast<int>(p.cells[0].size());
  p.region.y1 = p.region.y0 + static_cast<int>(p.cells.size());
}

void placeProbe(const std::string& file, PendingProbe& pp, int width, int height) {
  ScriptProbe& p = *pp.probe;
  if (p.form == ScriptProbe::Form::All) {
    p.region = {0, 0, width, height};
    return;
  }
  const PixelRect& r = p.region;
  if (r.x1 <= width && r.y1 <= height) return;
  const std::string window = std::to_string(width) + "x" + std::to_string(height) + " window";
  if (p.form == ScriptProbe::Form::Pixel)
    fail(file, pp.line, pp.xColumn, "pixel (" + std::to_string(r.x0) + "," + std::to_string(r.y0) + ") is outside the " +
                                  window + " (origin bottom-left)");
  fail(file, pp.line, pp.xColumn, "the " + std::to_string(r.x1 - r.x0) + "x" + std::to_string(r.y1 - r.y0) +
                                " region with bottom-left pixel (" + std::to_string(r.x0) + "," +
                                std::to_string(r.y0) + ") reaches outside the " + window);
}

}  // namespace mpr
