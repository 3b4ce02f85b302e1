// Reads a GL script exactly as `mpr gl` (with more than one thread) and
// bench/mesa_gl read it (the file read, then streamed command by command
// while checked on a thread beside) and executes nothing: the floor both
// sides of bench/compare_mesa share, printed there as "reader".
// Usage: read_gl_script SCRIPT
#include <cstdio>
#include <string>

#include "pipeline/gl_script.hpp"
#include "pipeline/script_check_thread.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: read_gl_script SCRIPT\n");
    return 2;
  }
  try {
    const std::string text = mpr::readScriptText(argv[1]);
    const mpr::Script header = mpr::scanScriptHeader(text, argv[1]);
    mpr::ScriptCheckThread check(text, argv[1]);
    std::size_t calls = 0;
    mpr::streamScript(text, header, [&](mpr::ScriptCommand&& c) { calls += c.kind == mpr::ScriptCommand::Kind::Call; });
    check.wait();  // a script error: the ScriptError below
    std::printf("%s: %zu calls read\n", argv[1], calls);
  } catch (const mpr::ScriptError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
