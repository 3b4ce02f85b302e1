// Runs a GL script on Mesa through OSMesa as a whole process, for
// bench/compare_mesa: the script is read with MPR's parser and streamed as
// `mpr gl` streams it (replayed as parsed; the reading finds the first
// script error, which ends the replay) through
// conformance/'s replayer (the one `mpr conform` uses), the buffers read
// back once at the end. Usage: mesa_gl [--driver llvmpipe|softpipe] SCRIPT
// (LP_NUM_THREADS sets llvmpipe's threads; Mesa's default is one a core).
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <string>

#include "conformance/mesa_replayer.hpp"
#include "script/gl_script.hpp"
#include "script/script_text.hpp"

int main(int argc, char** argv) {
  std::string driver = "llvmpipe", path;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--driver") == 0 && i + 1 < argc) driver = argv[++i];
    else if (path.empty() && argv[i][0] != '-') path = argv[i];
    else path.clear(), i = argc;
  }
  if (path.empty() || (driver != "llvmpipe" && driver != "softpipe")) {
    std::fprintf(stderr, "usage: mesa_gl [--driver llvmpipe|softpipe] SCRIPT\n");
    return 2;
  }
  try {
    // Streamed as `mpr gl` streams it with more than one thread: from the
    // header, the text parsed once, its reading the check.
    mpr::ScriptText text = mpr::ScriptText::ofFile(path);
    const mpr::Script header = mpr::scanScriptHeader(text, path);
    std::size_t calls = 0;
    const mpr::MesaReplay replay =
        mpr::replayOnMesa(header, driver, [&](const std::function<void(const mpr::ScriptCommand&)>& replay) {
          // Parsed on this thread, not ahead on one of its own as `mpr gl`
          // does: on two cores a reader thread competes with llvmpipe's
          // rasterizer threads and slows it (bathroom trace 1.07 -> 1.20 s,
          // measured), so each side reads the way it is fastest.
          mpr::streamScript(text, header, [&](mpr::ScriptCommand&& c) {
            calls += c.kind == mpr::ScriptCommand::Kind::Call;
            replay(c);
          });
        });
    std::printf("%s: %zu calls on %s\n", path.c_str(), calls, replay.renderer.c_str());
  } catch (const mpr::ScriptError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mesa_gl: %s\n", e.what());
    return 1;
  }
  return 0;
}
