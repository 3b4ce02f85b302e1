#include "framebuffer/script_probe.hpp"

#include <cstdlib>

#include "framebuffer/stencil_picture.hpp"

namespace mpr {
namespace {

using Value = std::array<std::int64_t, 4>;

int channels(ScriptProbe::Buffer b) {
  return b == ScriptProbe::Buffer::Color || b == ScriptProbe::Buffer::Accum ? 4 : 1;
}

// The stored value as the dumps hold it: integers, so the compare is exact
// (a colour read back as a float in 0..1 would round on the way).
Value read(const Framebuffer& fb, ScriptProbe::Buffer b, int x, int y) {
  switch (b) {
    case ScriptProbe::Buffer::Stencil: return {fb.stencil(x, y), 0, 0, 0};
    case ScriptProbe::Buffer::Depth: return {fb.depth(x, y), 0, 0, 0};
    case ScriptProbe::Buffer::Color: {
      const Rgba8& c = fb.color(x, y);
      return {c[0], c[1], c[2], c[3]};
    }
    case ScriptProbe::Buffer::Accum: {
      const std::int16_t* a = fb.accum(x, y);
      return {a[0], a[1], a[2], a[3]};
    }
  }
  return {};
}

std::string valueText(ScriptProbe::Buffer b, const Value& v) {
  if (channels(b) == 1) return std::to_string(v[0]);
  std::string o = "(";
  for (int i = 0; i < 4; ++i) {
    if (i) o += ",";
    o += std::to_string(v[static_cast<std::size_t>(i)]);
  }
  return o + ")";
}

bool holds(const ScriptProbe& p, const Value& found) {
  for (int i = 0; i < channels(p.buffer); ++i)
    if (std::llabs(found[static_cast<std::size_t>(i)] - p.expected[static_cast<std::size_t>(i)]) > p.tolerance)
      return false;
  return true;
}

// Appended piece by piece: `"(" + std::to_string(x)` draws a GCC 12
// -Wrestrict false positive (its memcpy of the prepended literal).
std::string point(int x, int y) {
  std::string text = "(";
  text += std::to_string(x);
  text += ',';
  text += std::to_string(y);
  text += ')';
  return text;
}

std::string expectedText(const ScriptProbe& p) {
  std::string o = valueText(p.buffer, p.expected);
  if (!p.expectedName.empty()) o = p.expectedName + " = " + o;
  if (p.tolerance > 0) o += " within " + std::to_string(p.tolerance);
  return o;
}

std::string regionText(const ScriptProbe& p) {
  const PixelRect& r = p.region;
  if (p.form == ScriptProbe::Form::All) return probeBufferName(p.buffer) + " all";
  return probeBufferName(p.buffer) + " rect " + std::to_string(r.x0) + " " + std::to_string(r.y0) + " " +
         std::to_string(r.x1 - r.x0) + " " + std::to_string(r.y1 - r.y0);
}

}  // namespace

bool probeHoldsAt(const ScriptProbe& p, const Framebuffer& fb, int x, int y);

namespace {

ProbeOutcome evaluatePicture(const ScriptProbe& p, const Framebuffer& fb) {
  ProbeOutcome out;
  for (int y = p.region.y0; y < p.region.y1 && out.passed; ++y)
    for (int x = p.region.x0; x < p.region.x1; ++x)
      if (!probeHoldsAt(p, fb, x, y)) {
        out = {false, "", x, y};
        break;
      }
  if (out.passed) return out;
  std::string report = stencilPictureMismatch(fb, p.region.x0, p.region.y0, p.picture);
  if (!report.empty() && report.back() == '\n') report.pop_back();
  out.message = "stencil picture at " + point(p.region.x0, p.region.y0) + ": " + report;
  return out;
}

}  // namespace

std::string probeBufferName(ScriptProbe::Buffer b) {
  switch (b) {
    case ScriptProbe::Buffer::Stencil: return "stencil";
    case ScriptProbe::Buffer::Depth: return "depth";
    case ScriptProbe::Buffer::Color: return "colour";
    case ScriptProbe::Buffer::Accum: return "accum";
  }
  return "?";
}

std::string probeText(const ScriptProbe& p) {
  switch (p.form) {
    case ScriptProbe::Form::Pixel:
      return probeBufferName(p.buffer) + " " + expectedText(p) + " at " + point(p.region.x0, p.region.y0);
    case ScriptProbe::Form::All:
    case ScriptProbe::Form::Rect: return regionText(p) + " " + expectedText(p);
    case ScriptProbe::Form::Picture: return "stencil picture at " + point(p.region.x0, p.region.y0);
  }
  return {};
}

bool probeHoldsAt(const ScriptProbe& p, const Framebuffer& fb, int x, int y) {
  if (p.form != ScriptProbe::Form::Picture) return holds(p, read(fb, p.buffer, x, y));
  const int h = static_cast<int>(p.cells.size());
  const int want = p.cells[static_cast<std::size_t>(p.region.y0 + h - 1 - y)][static_cast<std::size_t>(x - p.region.x0)];
  return want < 0 || want == fb.stencil(x, y);
}

std::vector<std::uint8_t> probeDifferenceImage(const ScriptProbe& p, const Framebuffer& fb) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(fb.width()) * static_cast<std::size_t>(fb.height()) * 3, 64);
  for (int y = p.region.y0; y < p.region.y1; ++y)
    for (int x = p.region.x0; x < p.region.x1; ++x) {
      std::uint8_t* px = &rgb[fb.index(x, y) * 3];
      const bool ok = probeHoldsAt(p, fb, x, y);
      px[0] = 255;
      px[1] = px[2] = ok ? 255 : 0;
    }
  return rgb;
}

ProbeOutcome evaluateProbe(const ScriptProbe& p, const Framebuffer& fb) {
  if (p.form == ScriptProbe::Form::Picture) return evaluatePicture(p, fb);
  ProbeOutcome out;
  std::size_t differ = 0;
  Value first{};
  for (int y = p.region.y0; y < p.region.y1; ++y)
    for (int x = p.region.x0; x < p.region.x1; ++x) {
      const Value v = read(fb, p.buffer, x, y);
      if (holds(p, v)) continue;
      if (differ++ == 0) {
        first = v;
        out.x = x;
        out.y = y;
      }
    }
  if (differ == 0) return out;
  out.passed = false;
  if (p.form == ScriptProbe::Form::Pixel) {
    out.message = probeBufferName(p.buffer) + " at " + point(out.x, out.y) + ": expected " + expectedText(p) +
                  ", found " + valueText(p.buffer, first);
    return out;
  }
  const std::size_t all = static_cast<std::size_t>(p.region.x1 - p.region.x0) *
                          static_cast<std::size_t>(p.region.y1 - p.region.y0);
  out.message = regionText(p) + ": expected " + expectedText(p) + " on all " + std::to_string(all) + " pixels, " +
                std::to_string(differ) + " differ; the first, " + point(out.x, out.y) + ", holds " +
                valueText(p.buffer, first);
  return out;
}

}  // namespace mpr
