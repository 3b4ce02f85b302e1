#include "stepper/pixel_history_text.hpp"

#include <sstream>

#include "stepper/gl_state_json.hpp"

namespace mpr {
namespace {

std::string hex(std::uint32_t v) {
  std::ostringstream o;
  o << std::hex << v;
  return o.str();
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
std::string stencilTestText(const StencilState& s, const std::string& before) {
  if (!s.enabled) return "stencil test off";
  std::string o = "stencil ";
  o += compareFuncName(s.func);
  o += " (";
  o += std::to_string(s.ref);
  o += " & 0x";
  o += hex(s.valueMask);
  o += " vs ";
  o += before;
  o += " & 0x";
  o += hex(s.valueMask);
  o += ")";
  return o;
}

}  // namespace

std::string fragmentLine(std::string_view callName, const FragmentState& s, FragmentFate fate,
                         const FragmentLineFields& f) {
  std::string o = "  line ";
  o += f.line;
  o += ' ';
  o += callName;
  o += ", fragment ";
  o += f.fragment;
  o += ": ";
  o += stencilTestText(s.stencil, f.stencilBefore);
  std::string depthTest = "depth ";
  depthTest += compareFuncName(s.depth.func);
  depthTest += " (";
  depthTest += f.depthIncoming;
  depthTest += " vs ";
  depthTest += f.depthBefore;
  depthTest += ")";
  switch (fate) {
    case FragmentFate::AlphaFailed: o += "; alpha test failed: nothing written"; break;
    case FragmentFate::StencilFailed:
      o += " failed; sfail ";
      o += stencilOpName(s.stencil.sfail);
      break;
    case FragmentFate::DepthFailed:
      if (s.stencil.enabled) o += " passed";
      o += "; ";
      o += depthTest;
      o += " failed";
      if (s.stencil.enabled) {
        o += "; dpfail ";
        o += stencilOpName(s.stencil.dpfail);
      }
      break;
    case FragmentFate::Written:
      if (s.stencil.enabled) o += " passed";
      if (s.depth.enabled) {
        o += "; ";
        o += depthTest;
        o += " passed";
      } else {
        o += "; depth test off";
      }
      if (s.stencil.enabled) {
        o += "; dppass ";
        o += stencilOpName(s.stencil.dppass);
      }
      o += "; colour ";
      o += f.colourAfter;
      break;
  }
  o += "; stencil ";
  o += f.stencilBefore;
  o += " -> ";
  o += f.stencilAfter;
  return o;
}

std::string changeLine(std::string_view callName, const ChangeLineFields& f) {
  std::string o = "  line ";
  for (std::string_view part : {std::string_view(f.line), std::string_view(" "), callName, std::string_view(": stencil "),
                                std::string_view(f.stencilBefore), std::string_view(" -> "),
                                std::string_view(f.stencilAfter), std::string_view(", depth "),
                                std::string_view(f.depthBefore), std::string_view(" -> "), std::string_view(f.depthAfter),
                                std::string_view(", colour "), std::string_view(f.colourBefore),
                                std::string_view(" -> "), std::string_view(f.colourAfter)})
    o += part;
  return o;
}

std::string pixelEventLine(const PixelEvent& e, const FragmentState& s) {
  const std::string_view call = glCallName(e.call->call);
  if (e.kind == PixelEvent::Kind::Change)
    return changeLine(call, {std::to_string(e.call->line), std::to_string(e.stencilBefore), std::to_string(e.stencilAfter),
                             std::to_string(e.depthBefore), std::to_string(e.depthAfter), rgbaText(e.colourBefore),
                             rgbaText(e.colourAfter)});
  return fragmentLine(call, s, e.fate,
                      {std::to_string(e.call->line), std::to_string(e.fragment), std::to_string(e.stencilBefore),
                       std::to_string(e.stencilAfter), std::to_string(e.depthBefore), std::to_string(e.depthIncoming),
                       rgbaText(e.colourAfter)});
}

std::string passHeaderLine(int pass, std::string_view label) {
  std::string o = "pass ";
  o += std::to_string(pass);
  o += " \"";
  o += label;
  o += '"';
  return o;
}

std::string rgbaText(const Rgba8& c) {
  std::string o = "(";
  for (int i = 0; i < 4; ++i) {
    if (i) o += ',';
    o += std::to_string(c[i]);
  }
  o += ')';
  return o;
}

std::string pixelValueText(std::uint32_t stencil, int stencilBits, std::uint32_t depth, const Rgba8& colour) {
  std::string o = "stencil ";
  o += std::to_string(stencil);
  o += " = 0x";
  o += hex(stencil);
  o += " = 0b";
  for (int b = stencilBits - 1; b >= 0; --b) o += ((stencil >> b) & 1) ? '1' : '0';
  o += ", depth ";
  o += std::to_string(depth);
  o += ", colour ";
  o += rgbaText(colour);
  return o;
}

}  // namespace mpr
