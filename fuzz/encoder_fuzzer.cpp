// The stepper page's encoders: a parsed script's buffers after each pass
// as frame deltas (cli/frame_delta_encoder), zlib-compressed and base64'd,
// and the input text as a JavaScript string literal (cli/page_encoding),
// checked to keep "</" escaped so it can never close a <script> element.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "cli/frame_delta_encoder.hpp"
#include "cli/page_encoding.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string literal = mpr::cli::jsString(text);
  if (literal.find("</") != std::string::npos) std::abort();
  (void)mpr::cli::base64(mpr::cli::zlibCompress(text, 1));
  mpr::Script script;
  try {
    script = mpr::parseScript(text, "fuzz.gls");
  } catch (const mpr::ScriptError&) {
    return 0;
  }
  if (script.width > 32 || script.height > 32 || script.callCount() > 2048) return 0;
  const auto profile = mpr::findProfile(script.profile.value_or("indigo"));
  if (!profile) return 0;
  mpr::GLContext gl(script.width, script.height, *profile);
  mpr::cli::FrameDeltaEncoder frames(script.width, script.height);
  mpr::ScriptHooks hooks;
  hooks.onPass = [&](const mpr::ScriptCommand&) { (void)mpr::cli::zlibCompress(frames.encode(gl.framebuffer()), 1); };
  mpr::runScript(script, gl, hooks);
  (void)frames.encode(gl.framebuffer());
  return 0;
}
