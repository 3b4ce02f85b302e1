// The scene's expect: list (docs/scene-format.md, "Expectations"): probes
// of the buffers at named points of the render, checked by mpr test.
#include <cctype>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "framebuffer/profile.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_section_readers.hpp"
#include "util/spelling.hpp"

namespace mpr {
namespace {

using scene_format::kExpectKeys;

void checkInWindow(const SceneNodeReader& in, const YAML::Node& at, const ScriptProbe& p, const RenderSettings& r) {
  const PixelRect& g = p.region;
  if (g.x1 <= r.width && g.y1 <= r.height) return;
  const std::string window = std::to_string(r.width) + "x" + std::to_string(r.height) + " window";
  if (p.form == ScriptProbe::Form::Pixel)
    in.fail(at, "pixel (" + std::to_string(g.x0) + "," + std::to_string(g.y0) + ") is outside the " + window +
                    " (origin bottom-left)");
  in.fail(at, "the " + std::to_string(g.x1 - g.x0) + "x" + std::to_string(g.y1 - g.y0) + " region with bottom-left pixel (" +
                  std::to_string(g.x0) + "," + std::to_string(g.y0) + ") reaches outside the " + window);
}

// [x, y], [x, y, width, height] or all, inside the window.
void readRegion(const SceneNodeReader& in, const YAML::Node& at, const std::string& what, const RenderSettings& r,
                ScriptProbe& p) {
  const std::string usage = what + " must be [x, y], [x, y, width, height] or all";
  if (at.IsScalar()) {
    if (at.Scalar() != "all") in.fail(at, usage + ", not '" + at.Scalar() + "'");
    p.form = ScriptProbe::Form::All;
    p.region = {0, 0, r.width, r.height};
    return;
  }
  if (!at.IsSequence() || (at.size() != 2 && at.size() != 4)) in.fail(at, usage);
  const int x = in.integer(at[0], what + " x", 0, 1 << 30), y = in.integer(at[1], what + " y", 0, 1 << 30);
  int w = 1, h = 1;
  if (at.size() == 4) {
    p.form = ScriptProbe::Form::Rect;
    w = in.integer(at[2], what + " width", 1, 1 << 30);
    h = in.integer(at[3], what + " height", 1, 1 << 30);
  }
  p.region = {x, y, x + w, y + h};
  checkInWindow(in, at, p, r);
}

// An integer, or ZERO, SHAD_MIN, SHAD_ZERO or MAX with an optional + n or
// - n: the 1994 paper's levels for the profile's stencil width (the
// formula of algorithms/stencil_levels.hpp: SHAD_MIN one-half, SHAD_ZERO
// three-quarters of the range).
std::int64_t stencilValue(const SceneNodeReader& in, const YAML::Node& v, const std::string& what, const Scene& s,
                          std::string& named) {
  const HardwareProfile profile = *findProfile(s.render.profile);
  const long max = static_cast<long>(profile.stencilMax());
  if (!v.IsScalar()) in.fail(v, what + " must be an integer or a stencil level (ZERO, SHAD_MIN, SHAD_ZERO, MAX, + or - n)");
  const std::string text = v.Scalar();
  if (!text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-' || text[0] == '+'))
    return in.integer(v, what, 0, max);
  std::size_t i = 0;
  while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
  const std::string level = text.substr(0, i);
  const long range = max + 1;
  static const std::vector<std::string_view> names = {"ZERO", "SHAD_MIN", "SHAD_ZERO", "MAX"};
  long base = 0;
  if (level == "ZERO") base = 0;
  else if (level == "SHAD_MIN") base = range / 2;
  else if (level == "SHAD_ZERO") base = range / 4 * 3;
  else if (level == "MAX") base = max;
  else {
    const std::string best = closestMatch(level, names, 3);
    in.fail(v, what + " '" + text + "' is not an integer or a stencil level" +
                   (best.empty() ? " (known: ZERO, SHAD_MIN, SHAD_ZERO, MAX)" : "; did you mean '" + best + "'?"));
  }
  while (i < text.size() && text[i] == ' ') ++i;
  long offset = 0;
  char sign = 0;
  if (i < text.size()) {
    sign = text[i++];
    while (i < text.size() && text[i] == ' ') ++i;
    const std::string digits = text.substr(i);
    if ((sign != '+' && sign != '-') || digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      in.fail(v, what + " '" + text + "' must be a level with an optional + n or - n, like SHAD_ZERO + 1");
    offset = std::stol(digits) * (sign == '-' ? -1 : 1);
  }
  const long value = base + offset;
  named = level + (sign ? std::string(" ") + sign + " " + std::to_string(offset < 0 ? -offset : offset) : "");
  if (value < 0 || value > max)
    in.fail(v, what + " " + named + " = " + std::to_string(value) + " is outside the " + std::to_string(profile.stencilBits) +
                   "-bit stencil of profile '" + profile.name + "' (0 .. " + std::to_string(max) + ")");
  return value;
}

void readValue(const SceneNodeReader& in, const YAML::Node& v, const std::string& what, const Scene& s, ScriptProbe& p) {
  const std::string name = what + " value";
  switch (p.buffer) {
    case ScriptProbe::Buffer::Stencil: p.expected[0] = stencilValue(in, v, name, s, p.expectedName); return;
    case ScriptProbe::Buffer::Depth: p.expected[0] = in.integer(v, name, 0, (1 << 24) - 1); return;
    case ScriptProbe::Buffer::Color:
    case ScriptProbe::Buffer::Accum: {
      const bool color = p.buffer == ScriptProbe::Buffer::Color;
      if (!v.IsSequence() || v.size() != 4)
        in.fail(v, name + " must be " + (color ? "[r, g, b, a], four bytes 0 .. 255" : "[r, g, b, a], four words -32768 .. 32767"));
      for (std::size_t i = 0; i < 4; ++i)
        p.expected[i] = color ? in.integer(v[i], name, 0, 255) : in.integer(v[i], name, -32768, 32767);
      return;
    }
  }
}

// Rows top-down (as framebuffer/stencil_picture.hpp reads them): cells a
// decimal 0 .. 255, . for 0, * for any value.
void readPicture(const SceneNodeReader& in, const YAML::Node& n, const RenderSettings& r, ScriptProbe& p) {
  if (!n.IsScalar()) in.fail(n, "expect picture must be a string of rows, like picture: |");
  std::istringstream lines(n.Scalar());
  for (std::string line; std::getline(lines, line);) {
    std::istringstream cells(line);
    std::vector<int> row;
    std::string text;
    for (std::string c; cells >> c;) {
      int v = -1;
      if (c == ".") v = 0;
      else if (c != "*") {
        const bool digits = c.size() <= 3 && c.find_first_not_of("0123456789") == std::string::npos;
        v = digits ? std::stoi(c) : 256;
        if (v > 255) in.fail(n, "expect picture cell '" + c + "' is not a stencil value 0 .. 255, '.' or '*'");
      }
      row.push_back(v);
      text += (text.empty() ? "" : " ") + c;
    }
    if (row.empty()) continue;
    if (!p.cells.empty() && row.size() != p.cells[0].size())
      in.fail(n, "expect picture row " + std::to_string(p.cells.size() + 1) + " has " + std::to_string(row.size()) +
                     " cells, the first row has " + std::to_string(p.cells[0].size()));
    p.cells.push_back(std::move(row));
    p.picture += text + "\n";
  }
  if (p.cells.empty()) in.fail(n, "expect picture has no rows");
  p.form = ScriptProbe::Form::Picture;
  p.region.x1 = p.region.x0 + static_cast<int>(p.cells[0].size());
  p.region.y1 = p.region.y0 + static_cast<int>(p.cells.size());
  checkInWindow(in, n, p, r);
}

SceneExpectation readExpectation(const SceneNodeReader& in, const YAML::Node& n, const Scene& s) {
  in.checkKeys(n, kExpectKeys, "an expectation");
  SceneExpectation e;
  e.line = n.Mark().line + 1;
  if (!n["after"]) in.fail(n, "an expectation needs after: a text of the pass label (mpr step SCENE lists them), or end");
  e.after = in.string(n["after"], "expect after");
  e.afterLine = n["after"].Mark().line + 1;
  e.afterColumn = n["after"].Mark().column + 1;
  if (e.after.empty()) in.fail(n["after"], "expect after must not be empty");
  for (const char* k : {"occurrence", "level", "light"})
    if (e.atEnd() && n[k])
      in.fail(n[k], std::string("expect after: end takes no ") + k + " (the finished render is one point)");
  if (n["occurrence"]) e.occurrence = in.integer(n["occurrence"], "expect occurrence", 1, 1 << 30);
  if (n["level"]) e.level = in.integer(n["level"], "expect level", 0, s.render.recursionDepth);
  if (n["light"]) {
    if (s.lights.empty()) in.fail(n["light"], "expect light: the scene has no lights");
    e.light = in.integer(n["light"], "expect light", 0, static_cast<long>(s.lights.size()) - 1);
  }
  ScriptProbe& p = e.probe;
  static const std::pair<const char*, ScriptProbe::Buffer> buffers[] = {
      {"stencil", ScriptProbe::Buffer::Stencil}, {"depth", ScriptProbe::Buffer::Depth},
      {"color", ScriptProbe::Buffer::Color}, {"accum", ScriptProbe::Buffer::Accum}};
  const char* buffer = nullptr;
  for (const auto& [name, b] : buffers) {
    if (!n[name]) continue;
    if (buffer) in.fail(n[name], std::string("an expectation probes one buffer: give ") + buffer + " or " + name + ", not both");
    buffer = name;
    p.buffer = b;
  }
  if (!buffer) in.fail(n, "an expectation needs the pixels it probes: stencil, depth, color or accum");
  const std::string what = std::string("expect ") + buffer;
  const YAML::Node at = n[buffer];
  const bool picture = static_cast<bool>(n["picture"]);
  if (picture && n["value"]) in.fail(n["picture"], "an expectation gives value or picture, not both");
  if (!picture && !n["value"]) in.fail(n, "an expectation needs a value (or, for stencil [x, y], a picture)");
  if (n["tolerance"] && p.buffer != ScriptProbe::Buffer::Color)
    in.fail(n["tolerance"], "expect tolerance is for color only");
  readRegion(in, at, what, s.render, p);
  if (picture) {
    if (p.buffer != ScriptProbe::Buffer::Stencil || p.form != ScriptProbe::Form::Pixel)
      in.fail(n["picture"], "expect picture takes stencil: [x, y], the picture's bottom-left pixel");
    readPicture(in, n["picture"], s.render, p);
    return e;
  }
  readValue(in, n["value"], what, s, p);
  if (n["tolerance"]) p.tolerance = in.integer(n["tolerance"], "expect tolerance", 0, 255);
  return e;
}

}  // namespace

void readExpectations(const SceneNodeReader& in, const YAML::Node& list, Scene& s) {
  if (!list.IsSequence()) in.fail(list, "expect must be a list of expectations, like - {after: end, stencil: [0, 0], value: ZERO}");
  in.checkCount(list, "expect", kMaxSceneExpectations);
  for (const YAML::Node& n : list) s.expectations.push_back(readExpectation(in, n, s));
}

}  // namespace mpr
