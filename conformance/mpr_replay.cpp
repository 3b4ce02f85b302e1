#include "conformance/mpr_replay.hpp"

#include "pipeline/gl/gl_context.hpp"
#include "pipeline/gl/gl_enums.hpp"
#include "script/gl_dispatch.hpp"
#include "pipeline/gl/gl_emulator.hpp"
#include "script/gl_script_runner.hpp"  // glErrorReport

namespace mpr {

BufferSet collectBuffers(const std::string& point, const Framebuffer& fb) {
  BufferSet b;
  b.point = point;
  b.width = fb.width();
  b.height = fb.height();
  for (const Rgba8& c : fb.colorData()) b.color.insert(b.color.end(), c.begin(), c.end());
  b.depth = fb.depthData();
  b.stencil = fb.stencilData();
  return b;
}

MprReplay replayOnMpr(const Script& script, const HardwareProfile& profile, unsigned departures, int threads) {
  GLContext gl(script.width, script.height, profile);
  gl.emulateMesaDepartures(departures);
  gl.setThreads(threads);
  MprReplay out;
  // Errors are read as the Mesa replayer reads them: after every call outside
  // glBegin/glEnd (glGetError is itself an error inside), so an error raised
  // between them is reported at glEnd, as GL keeps it.
  bool inBegin = false;
  GLEmulator emulator(gl);
  for (const ScriptCommand& c : script.commands) {
    if (c.kind == ScriptCommand::Kind::Snapshot) {
      gl.prepareRead();
      out.snapshots.push_back(collectBuffers(c.label, gl.framebuffer()));
    }
    dispatch(emulator, c);
    if (c.kind != ScriptCommand::Kind::Call) continue;
    if (c.call == GLCall::Begin) inBegin = true;
    if (c.call == GLCall::End) inBegin = false;
    if (inBegin) continue;
    if (const std::uint32_t e = gl.getError())
      out.glErrors.push_back(glErrorReport(c, e));
  }
  out.snapshots.push_back(collectBuffers("final", gl.framebuffer()));
  return out;
}

}  // namespace mpr
