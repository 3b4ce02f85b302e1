#pragma once
// The probe directives of a GL script (@expect, @expect-picture): parsed
// while the script is read, placed in the window when its size is known
// (the header's @framebuffer, or the whole script's end).
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framebuffer/script_probe.hpp"
#include "script/script_line.hpp"

namespace mpr {

// A probe while parsing: where its coordinates were written, to report a
// pixel outside the window at them once @framebuffer is known.
struct PendingProbe {
  std::shared_ptr<ScriptProbe> probe;
  std::size_t command = 0;
  int line = 0, column = 0;  // the directive
  int xColumn = 0;           // its X (0 for all)
};

// An integer as a script writes it: decimal or 0x hex, an optional sign;
// nothing else on the token.
std::optional<long long> parseScriptInteger(std::string_view t);

// @expect BUFFER X Y VALUE... | BUFFER all VALUE... | BUFFER rect X Y W H VALUE...
PendingProbe parseExpect(const std::string& file, const std::vector<ScriptToken>& toks, int line);
// @expect-picture stencil X Y, rows until @end (X Y: the bottom-left pixel).
PendingProbe parseExpectPicture(const std::string& file, const std::vector<ScriptToken>& toks, int line);
// One row of the picture: `.` for 0, `*` for any value, or a decimal 0..255.
void addPictureRow(const std::string& file, PendingProbe& pp, const std::vector<ScriptToken>& toks, int line);
// The picture's region, from its rows.
void finishPicture(PendingProbe& pp);
// Places the probe in a width x height window: a probe reaching outside it
// is the script's error at its X.
void placeProbe(const std::string& file, PendingProbe& pp, int width, int height);

}  // namespace mpr
