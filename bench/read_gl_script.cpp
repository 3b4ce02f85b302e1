// Reads a GL script as `mpr gl` (with more than one thread) and
// bench/mesa_gl read it (the header scanned, then the file read a piece at
// a time and streamed command by command, which finds its first error) and executes
// nothing: the floor both sides of bench/compare_mesa share, printed there
// as "reader".
// Usage: read_gl_script SCRIPT
#include <cstdio>
#include <string>

#include "script/gl_script.hpp"
#include "script/script_text.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: read_gl_script SCRIPT\n");
    return 2;
  }
  try {
    mpr::ScriptText text = mpr::ScriptText::ofFile(argv[1]);
    const mpr::Script header = mpr::scanScriptHeader(text, argv[1]);
    std::size_t calls = 0;
    mpr::streamScript(text, header, [&](mpr::ScriptCommand&& c) { calls += c.kind == mpr::ScriptCommand::Kind::Call; });
    std::printf("%s: %zu calls read\n", argv[1], calls);
  } catch (const mpr::ScriptError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
