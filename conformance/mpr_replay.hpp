#pragma once
// Runs a GL script on the emulator and collects the same buffer sets the Mesa
// replayer collects (every @snapshot, then "final").
#include <string>
#include <vector>

#include "conformance/buffer_set.hpp"
#include "framebuffer/profile.hpp"
#include "script/gl_script.hpp"

namespace mpr {

class Framebuffer;

struct MprReplay {
  std::vector<BufferSet> snapshots;
  std::vector<std::string> glErrors;  // "LINE: GL_INVALID_ENUM in glX"
};

// `departures`: MesaDeparture bits to emulate (pipeline/gl_context.hpp), for
// telling which differences a known departure of Mesa's explains; `threads`:
// GLContext::setThreads (the buffers are the same at any count).
// A framebuffer's colour, depth and stencil as a BufferSet named `point`.
BufferSet collectBuffers(const std::string& point, const Framebuffer& fb);

MprReplay replayOnMpr(const Script& script, const HardwareProfile& profile, unsigned departures = 0, int threads = 1);

}  // namespace mpr
