// The probe parser (@expect, @expect-picture; docs/gl-script-directives.md):
// every buffer and form parsed into its ScriptProbe, and every script error
// at its exact line and column.
#include <gtest/gtest.h>

#include <string>

#include "script/gl_script.hpp"
#include "script/script_probe.hpp"

namespace mpr {
namespace {

using Buffer = ScriptProbe::Buffer;
using Form = ScriptProbe::Form;

// The one probe of a script whose other lines are directives or calls.
const ScriptCommand& onlyProbe(const Script& s) {
  for (const ScriptCommand& c : s.commands)
    if (c.kind == ScriptCommand::Kind::Probe) return c;
  throw std::runtime_error("no probe");
}

Script parse(const std::string& text) { return parseScript(text, "p.gls"); }

// The one probe of a script, by value (the script is gone after the call).
ScriptProbe probeOf(const std::string& text) { return *onlyProbe(parse(text)).probe; }

TEST(ScriptProbeParser, StencilPixel) {
  const Script s = parse("@framebuffer 8 4\n@expect stencil 3 2 129   # a comment\n");
  ASSERT_EQ(s.probeCount(), 1u);
  const ScriptCommand& c = onlyProbe(s);
  EXPECT_EQ(c.line, 2);
  EXPECT_EQ(c.label, "@expect stencil 3 2 129");
  const ScriptProbe& p = *c.probe;
  EXPECT_EQ(p.buffer, Buffer::Stencil);
  EXPECT_EQ(p.form, Form::Pixel);
  EXPECT_EQ(p.region.x0, 3);
  EXPECT_EQ(p.region.y0, 2);
  EXPECT_EQ(p.region.x1, 4);
  EXPECT_EQ(p.region.y1, 3);
  EXPECT_EQ(p.expected[0], 129);
  EXPECT_EQ(p.tolerance, 0);
  EXPECT_EQ(probeText(p), "stencil 129 at (3,2)");
}

TEST(ScriptProbeParser, DepthPixelTakesTheStoredInteger) {
  const ScriptProbe p = probeOf("@expect depth 0 255 16777215\n");
  EXPECT_EQ(p.buffer, Buffer::Depth);
  EXPECT_EQ(p.form, Form::Pixel);
  EXPECT_EQ(p.region.y0, 255);
  EXPECT_EQ(p.expected[0], 16777215);
}

TEST(ScriptProbeParser, ColourWithAndWithoutTolerance) {
  const Script s = parse("@expect color 1 1 255 0 0 255\n@expect color 1 1 10 20 30 40 2\n");
  ASSERT_EQ(s.probeCount(), 2u);
  const ScriptProbe& exact = *s.commands[0].probe;
  EXPECT_EQ(exact.buffer, Buffer::Color);
  EXPECT_EQ(exact.expected, (std::array<std::int64_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(exact.tolerance, 0);
  const ScriptProbe& within = *s.commands[1].probe;
  EXPECT_EQ(within.expected, (std::array<std::int64_t, 4>{10, 20, 30, 40}));
  EXPECT_EQ(within.tolerance, 2);
  EXPECT_EQ(probeText(within), "colour (10,20,30,40) within 2 at (1,1)");
}

TEST(ScriptProbeParser, AccumTakesSignedWords) {
  const ScriptProbe p = probeOf("@expect accum 0 0 -32768 0 32767 0x10\n");
  EXPECT_EQ(p.buffer, Buffer::Accum);
  EXPECT_EQ(p.expected, (std::array<std::int64_t, 4>{-32768, 0, 32767, 16}));
}

TEST(ScriptProbeParser, AllCoversTheWindowKnownAtTheEnd) {
  // @framebuffer comes first in a script, but the region is the window's
  // whatever it is: the default 256x256 without one.
  const ScriptProbe p = probeOf("@framebuffer 6 5\n@expect stencil all 0\n");
  EXPECT_EQ(p.form, Form::All);
  EXPECT_EQ(p.region.x0, 0);
  EXPECT_EQ(p.region.y0, 0);
  EXPECT_EQ(p.region.x1, 6);
  EXPECT_EQ(p.region.y1, 5);
  EXPECT_EQ(probeText(p), "stencil all 0");
  const ScriptProbe d = probeOf("@expect depth all 7\n");
  EXPECT_EQ(d.region.x1, 256);
  EXPECT_EQ(d.region.y1, 256);
  const ScriptProbe c = probeOf("@expect color all 0 0 0 255 1\n");
  EXPECT_EQ(c.tolerance, 1);
  EXPECT_EQ(probeOf("@expect accum all 0 0 0 0\n").buffer, Buffer::Accum);
}

TEST(ScriptProbeParser, Rect) {
  const ScriptProbe p = probeOf("@framebuffer 8 8\n@expect stencil rect 2 1 3 4 5\n");
  EXPECT_EQ(p.form, Form::Rect);
  EXPECT_EQ(p.region.x0, 2);
  EXPECT_EQ(p.region.y0, 1);
  EXPECT_EQ(p.region.x1, 5);
  EXPECT_EQ(p.region.y1, 5);
  EXPECT_EQ(p.expected[0], 5);
  EXPECT_EQ(probeText(p), "stencil rect 2 1 3 4 5");
  const ScriptProbe c = probeOf("@framebuffer 8 8\n@expect color rect 0 0 8 8 1 2 3 4 9\n");
  EXPECT_EQ(c.region.x1, 8);
  EXPECT_EQ(c.tolerance, 9);
}

TEST(ScriptProbeParser, PictureRowsTopDown) {
  const Script s = parse(
      "@framebuffer 8 8\n"
      "@expect-picture stencil 1 2   # bottom-left pixel\n"
      "  .  1   *\n"
      "\n"
      "  255 .  7   # comments and blank lines are allowed inside\n"
      "@end\n"
      "glFinish\n");
  ASSERT_EQ(s.probeCount(), 1u);
  const ScriptCommand& c = s.commands[0];
  EXPECT_EQ(c.line, 2);
  EXPECT_EQ(c.label, "@expect-picture stencil 1 2");
  const ScriptProbe& p = *c.probe;
  EXPECT_EQ(p.buffer, Buffer::Stencil);
  EXPECT_EQ(p.form, Form::Picture);
  EXPECT_EQ(p.region.x0, 1);
  EXPECT_EQ(p.region.y0, 2);
  EXPECT_EQ(p.region.x1, 4);
  EXPECT_EQ(p.region.y1, 4);
  ASSERT_EQ(p.cells.size(), 2u);
  EXPECT_EQ(p.cells[0], (std::vector<int>{0, 1, -1}));
  EXPECT_EQ(p.cells[1], (std::vector<int>{255, 0, 7}));
  EXPECT_EQ(p.picture, ". 1 *\n255 . 7\n");
  EXPECT_EQ(probeText(p), "stencil picture at (1,2)");
  EXPECT_EQ(s.commands[1].call, GLCall::Finish);  // the script goes on after @end
}

TEST(ScriptProbeParser, ProbesKeepTheirPlaceAmongCallsPassesAndSnapshots) {
  const Script s = parse(
      "@pass one\n"
      "glClear GL_STENCIL_BUFFER_BIT\n"
      "@expect stencil 0 0 0\n"
      "@snapshot a\n"
      "@expect-picture stencil 0 0\n"
      ".\n"
      "@end\n"
      "@pass two\n");
  ASSERT_EQ(s.commands.size(), 6u);
  EXPECT_EQ(s.commands[0].kind, ScriptCommand::Kind::Pass);
  EXPECT_EQ(s.commands[2].kind, ScriptCommand::Kind::Probe);
  EXPECT_EQ(s.commands[3].kind, ScriptCommand::Kind::Snapshot);
  EXPECT_EQ(s.commands[4].kind, ScriptCommand::Kind::Probe);
  EXPECT_EQ(s.commands[4].line, 5);
  EXPECT_EQ(s.commands[5].kind, ScriptCommand::Kind::Pass);
  EXPECT_EQ(s.probeCount(), 2u);
}

// parseScript's error as LINE:COLUMN: message.
std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const ScriptError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("p.gls:", 0), 0u) << what;
    return std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": " + what.substr(what.find(": ") + 2);
  }
  return "no error";
}

TEST(ScriptProbeParser, ExpectErrorsAreLocated) {
  // Columns are 1-based; "at the end" is just past the last token.
  EXPECT_EQ(errorOf("@expect\n"),
            "1:1: @expect takes stencil|depth|color|accum, then X Y, all, or rect X Y W H, then the value");
  EXPECT_EQ(errorOf("  @expect stencils 0 0 0\n"),
            "1:11: unknown buffer 'stencils' (known: stencil, depth, color, accum)");
  EXPECT_EQ(errorOf("@expect stencil\n"), "1:16: @expect stencil needs X Y, all, or rect X Y W H");
  EXPECT_EQ(errorOf("@expect stencil 1   # y missing\n"), "1:18: @expect stencil needs X Y");
  EXPECT_EQ(errorOf("@expect depth rect 1 2 3\n"), "1:25: @expect depth needs X Y W H");
  EXPECT_EQ(errorOf("@expect stencil 0.5 0 1\n"), "1:17: X must be an integer, not '0.5'");
  EXPECT_EQ(errorOf("@expect stencil 0 y 1\n"), "1:19: Y must be an integer, not 'y'");
  EXPECT_EQ(errorOf("@expect stencil -1 0 1\n"), "1:17: X -1 is outside 0..1073741824");
  EXPECT_EQ(errorOf("@expect stencil rect 0 0 0 1 1\n"), "1:26: W 0 is outside 1..1073741824");
  EXPECT_EQ(errorOf("@expect stencil rect 0 0 1 -2 1\n"), "1:28: H -2 is outside 1..1073741824");
  EXPECT_EQ(errorOf("@expect stencil 0 0\n"), "1:20: @expect stencil takes one value, got 0 value(s)");
  EXPECT_EQ(errorOf("@expect stencil 0 0 1 2\n"), "1:23: @expect stencil takes one value, got 2 value(s)");
  EXPECT_EQ(errorOf("@expect depth all 1 2\n"), "1:21: @expect depth takes one value, got 2 value(s)");
  EXPECT_EQ(errorOf("@expect color 0 0 1 2 3\n"),
            "1:24: @expect color takes R G B A (bytes) and an optional tolerance, got 3 value(s)");
  EXPECT_EQ(errorOf("@expect color 0 0 1 2 3 4 5 6\n"),
            "1:29: @expect color takes R G B A (bytes) and an optional tolerance, got 6 value(s)");
  EXPECT_EQ(errorOf("@expect accum 0 0 1 2 3 4 5\n"), "1:27: @expect accum takes four words R G B A, got 5 value(s)");
  EXPECT_EQ(errorOf("@expect stencil 0 0 256\n"), "1:21: stencil value 256 is outside 0..255");
  EXPECT_EQ(errorOf("@expect stencil 0 0 x1\n"), "1:21: stencil value must be an integer, not 'x1'");
  EXPECT_EQ(errorOf("@expect depth all 16777216\n"), "1:19: depth value 16777216 is outside 0..16777215");
  EXPECT_EQ(errorOf("@expect color 0 0 0 256 0 0\n"), "1:21: color value 256 is outside 0..255");
  EXPECT_EQ(errorOf("@expect color 0 0 0 0 0 0 256\n"), "1:27: the tolerance 256 is outside 0..255");
  EXPECT_EQ(errorOf("@expect accum all 0 -32769 0 0\n"), "1:21: accum value -32769 is outside -32768..32767");
}

TEST(ScriptProbeParser, PictureErrorsAreLocated) {
  EXPECT_EQ(errorOf("@expect-picture depth 0 0\n.\n@end\n"),
            "1:1: @expect-picture takes stencil X Y (the picture's bottom-left pixel), then rows up to @end");
  EXPECT_EQ(errorOf("@expect-picture stencil 0\n"),
            "1:1: @expect-picture takes stencil X Y (the picture's bottom-left pixel), then rows up to @end");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 q\n.\n@end\n"), "1:27: Y must be an integer, not 'q'");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n. .\n"), "1:1: @expect-picture without @end");
  EXPECT_EQ(errorOf("\n  @end\n"), "2:3: @end without @expect-picture");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n.\n@end now\n"), "3:6: @end takes nothing");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n@end\n"), "2:1: @expect-picture has no rows before @end");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n. .\n . . .\n@end\n"),
            "3:2: picture row has 3 cells, the first row has 2");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n. x\n@end\n"),
            "2:3: picture cell 'x' is not a stencil value 0..255, '.' or '*'");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n.  256\n@end\n"),
            "2:4: picture cell '256' is not a stencil value 0..255, '.' or '*'");
  EXPECT_EQ(errorOf("@expect-picture stencil 0 0\n.\n@pass next\n"),
            "3:1: picture cell '@pass' is not a stencil value 0..255, '.' or '*' (is @end missing?)");
}

TEST(ScriptProbeParser, PlacementErrorsAreLocatedAtX) {
  EXPECT_EQ(errorOf("glBegin GL_TRIANGLES\n @expect stencil 0 0 0\nglEnd\n"), "2:2: @expect between glBegin and glEnd");
  EXPECT_EQ(errorOf("glBegin GL_QUADS\n@expect-picture stencil 0 0\n.\n@end\nglEnd\n"),
            "2:1: @expect-picture between glBegin and glEnd");
  EXPECT_EQ(errorOf("@framebuffer 8 8\n@expect stencil 3 8 0\n"),
            "2:17: pixel (3,8) is outside the 8x8 window (origin bottom-left)");
  EXPECT_EQ(errorOf("@expect depth  300 0 0\n"), "1:16: pixel (300,0) is outside the 256x256 window (origin bottom-left)");
  EXPECT_EQ(errorOf("@framebuffer 8 8\n@expect color rect 6 0 3 1 0 0 0 0\n"),
            "2:20: the 3x1 region with bottom-left pixel (6,0) reaches outside the 8x8 window");
  EXPECT_EQ(errorOf("@framebuffer 2 2\n@expect-picture stencil 1 0\n. .\n@end\n"),
            "2:25: the 2x1 region with bottom-left pixel (1,0) reaches outside the 2x2 window");
}

}  // namespace
}  // namespace mpr
