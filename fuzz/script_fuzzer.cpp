// The GL script parser, and the runner on a small window: any bytes give a
// Script or a ScriptError; a parsed script runs to the end (GL errors are
// reported, never crash). Windows are capped at 64x64 and scripts at 4096
// calls so that one input stays fast. Read in pieces of whole lines (as
// `mpr gl` reads a file), a script is checked as its whole text is: the
// same error, or none.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"
#include "script/script_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto checkError = [&](std::size_t pieceBytes) -> std::string {
    try {
      mpr::ScriptText pieces = mpr::ScriptText::ofString(text, pieceBytes);
      mpr::checkScript(pieces, "fuzz.gls");
    } catch (const mpr::ScriptError& e) {
      return e.what();
    }
    return "";
  };
  if (checkError(std::string_view::npos) != checkError(1 + size % 61)) __builtin_trap();
  mpr::Script script;
  try {
    script = mpr::parseScript(text, "fuzz.gls");
  } catch (const mpr::ScriptError&) {
    return 0;
  }
  if (script.width > 64 || script.height > 64 || script.callCount() > 4096) return 0;
  const auto profile = mpr::findProfile(script.profile.value_or("indigo"));
  if (!profile) return 0;
  mpr::GLContext gl(script.width, script.height, *profile);
  mpr::runScript(script, gl);
  return 0;
}
