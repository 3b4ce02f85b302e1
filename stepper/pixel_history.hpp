#pragma once
// A pixel's history as text: what `mpr step --pixel` prints, and what
// `mpr test` shows under a failing probe. One run of the script with a
// recorder on the pixel; the lines come from pixel_history_text.
#include <cstddef>
#include <string>

#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"

namespace mpr {

// Runs the first `commands` commands of `script` on `gl` (a fresh context of
// the script's size) recording pixel (x, y), and returns the history: each
// pass's header line before its first event line, every line ending in '\n'.
// GL errors are not reported (the script's own run reports them).
std::string recordPixelHistory(const Script& script, GLContext& gl, int x, int y,
                               std::size_t commands = static_cast<std::size_t>(-1));

}  // namespace mpr
