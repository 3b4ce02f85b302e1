#pragma once
// The lines of a pixel's history, as `mpr step --pixel` prints them and the
// stepper page shows them. One formatter for both: the command line passes
// the numbers as text, the page writer passes placeholders ("{s0}") and the
// page's script fills them in, so the two can never word a line differently.
#include <cstdint>
#include <string>
#include <string_view>

#include "framebuffer/fragment_ops.hpp"
#include "stepper/pixel_event_recorder.hpp"

namespace mpr {

// What a fragment line shows that changes from fragment to fragment.
struct FragmentLineFields {
  std::string line;           // script line of the call
  std::string fragment;       // 1, 2, ...: the fragment's rank at this pixel within the call
  std::string stencilBefore, stencilAfter;
  std::string depthBefore, depthIncoming;
  std::string colourAfter;    // "(r,g,b,a)"
};

// "  line 20 glEnd, fragment 1: stencil GL_ALWAYS (0 & 0xff vs 192 & 0xff) passed; ...; stencil 192 -> 193"
// `s` is the per-fragment state the call ran with; which parts appear depends
// on it and on the fate (a failed stencil test has no depth part, ...).
std::string fragmentLine(std::string_view callName, const FragmentState& s, FragmentFate fate,
                         const FragmentLineFields& f);

// What a clear or an accumulation return changed at the pixel.
struct ChangeLineFields {
  std::string line;
  std::string stencilBefore, stencilAfter;
  std::string depthBefore, depthAfter;
  std::string colourBefore, colourAfter;
};

// "  line 8 glClear: stencil 0 -> 192, depth 0 -> 0, colour (0,0,0,0) -> (0,0,0,0)"
std::string changeLine(std::string_view callName, const ChangeLineFields& f);

// The line of one recorded event, with its numbers.
std::string pixelEventLine(const PixelEvent& e, const FragmentState& s);

// "pass 2 \"label\"": the header before a pass's lines.
std::string passHeaderLine(int pass, std::string_view label);

// "(255,255,255,255)"
std::string rgbaText(const Rgba8& c);

// "stencil 194 = 0xc2 = 0b11000010, depth 0, colour (255,255,255,255)": a
// pixel's values, the stencil in decimal, hex and binary (`stencilBits` digits).
std::string pixelValueText(std::uint32_t stencil, int stencilBits, std::uint32_t depth, const Rgba8& colour);

}  // namespace mpr
