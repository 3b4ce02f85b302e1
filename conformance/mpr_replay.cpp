#include "conformance/mpr_replay.hpp"

#include "pipeline/gl_context.hpp"
#include "pipeline/gl_enums.hpp"
#include "pipeline/gl_script_runner.hpp"

namespace mpr {
namespace {

BufferSet collect(const std::string& point, const Framebuffer& fb) {
  BufferSet b;
  b.point = point;
  b.width = fb.width();
  b.height = fb.height();
  for (const Rgba8& c : fb.colorData()) b.color.insert(b.color.end(), c.begin(), c.end());
  b.depth = fb.depthData();
  b.stencil = fb.stencilData();
  return b;
}

}  // namespace

MprReplay replayOnMpr(const Script& script, const HardwareProfile& profile) {
  GLContext gl(script.width, script.height, profile);
  MprReplay out;
  ScriptHooks hooks;
  hooks.onSnapshot = [&](const ScriptCommand& c, const GLContext& ctx) {
    out.snapshots.push_back(collect(c.label, ctx.framebuffer()));
  };
  hooks.onGLError = [&](const ScriptCommand& c, std::uint32_t e) {
    out.glErrors.push_back(std::to_string(c.line) + ": " + std::string(glErrorName(e)) + " in " +
                           std::string(glCallName(c.call)));
  };
  runScript(script, gl, hooks);
  out.snapshots.push_back(collect("final", gl.framebuffer()));
  return out;
}

}  // namespace mpr
