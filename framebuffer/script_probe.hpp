#pragma once
// Probes: assertions on a buffer at one point of a GL script
// (docs/gl-script-directives.md, `@expect` and `@expect-picture`) or of a
// scene's render (docs/scene-format.md, `expect:`), after
// piglit's `probe rgba x y r g b a`. A probe reads the framebuffer as it is
// when the script reaches it; it never changes GL state, so a replay that
// ignores probes (Mesa's) draws the same bytes.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/framebuffer.hpp"

namespace mpr {

struct ScriptProbe {
  enum class Buffer : std::uint8_t { Stencil, Depth, Color, Accum };
  enum class Form : std::uint8_t { Pixel, All, Rect, Picture };
  Buffer buffer = Buffer::Stencil;
  Form form = Form::Pixel;
  // The pixels probed, window coordinates (origin bottom-left). All: set to
  // the whole window once the window's size is known.
  PixelRect region;
  // Pixel, All, Rect: the expected value. Stencil and depth use word 0 (the
  // stored integer); colour the four bytes; accumulation the four signed
  // 16-bit words as accum.npy holds them (32767 stands for 1.0).
  std::array<std::int64_t, 4> expected{};
  // The expected value's name when it was written as one (a scene's
  // `SHAD_ZERO + 1`): messages show "SHAD_ZERO + 1 = 193". Empty: a number.
  std::string expectedName;
  // Colour only: the largest difference accepted per channel (0: exact).
  int tolerance = 0;
  // Picture: the rows top-down, as written (stencilPictureMismatch reads
  // them), and the parsed cells, row 0 the top row, -1 for `*`.
  std::string picture;
  std::vector<std::vector<int>> cells;
};

// What a probe found. `x`, `y` is the first pixel that does not hold
// (bottom row first, left to right), for the pixel's history.
struct ProbeOutcome {
  bool passed = true;
  std::string message;  // empty when passed
  int x = -1, y = -1;
};

// "stencil", "depth", "colour", "accum".
std::string probeBufferName(ScriptProbe::Buffer b);

// The probe's expectation in words ("stencil 1 at (3,4)"), for listings.
std::string probeText(const ScriptProbe& p);

ProbeOutcome evaluateProbe(const ScriptProbe& p, const Framebuffer& fb);

// Whether pixel (x, y) of the probe's region holds what the probe expects.
bool probeHoldsAt(const ScriptProbe& p, const Framebuffer& fb, int x, int y);

// The window as an RGB difference image (rows bottom-up, as the framebuffer
// stores them): pixels outside the probe's region dark grey, pixels that hold
// white, pixels that do not red.
std::vector<std::uint8_t> probeDifferenceImage(const ScriptProbe& p, const Framebuffer& fb);

}  // namespace mpr
