#pragma once
// Replays a GL script through real OpenGL calls on Mesa's OSMesa
// (llvmpipe or softpipe), with the buffer configuration of the `mesa` profile:
// RGBA8, 24-bit depth, 8-bit stencil, 16-bit accumulation, Y up.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "conformance/buffer_set.hpp"
#include "script/gl_script.hpp"

namespace mpr {

class MesaUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MesaReplay {
  std::vector<BufferSet> snapshots;  // in script order, then "final"
  std::vector<std::string> glErrors; // "LINE: GL_INVALID_ENUM in glX"
  std::string renderer;              // GL_RENDERER as Mesa reports it
};

// `driver` is "llvmpipe" or "softpipe" (set through GALLIUM_DRIVER before the
// context is created). Throws MesaUnavailable when no context can be made.
MesaReplay replayOnMesa(const Script& script, const std::string& driver);
// The same replay for a streamed script (streamScript): `header` gives the
// window, and `feed` is called once with the function that replays one command.
using MesaCommandFeed = std::function<void(const std::function<void(const ScriptCommand&)>& replay)>;
MesaReplay replayOnMesa(const Script& header, const std::string& driver, const MesaCommandFeed& feed);

}  // namespace mpr
