// mpr: the command-line front end. Thin by design: it parses arguments and
// calls the libraries.
#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>
#include <new>

#include "cli/accuracy_command.hpp"
#include "cli/conform_command.hpp"
#include "cli/gl_command.hpp"
#include "cli/info_command.hpp"
#include "cli/process_policy.hpp"
#include "cli/reference_command.hpp"
#include "cli/render_command.hpp"
#include "cli/step_command.hpp"
#include "cli/test_command.hpp"
#include "util/signal_cleanup.hpp"

int main(int argc, char** argv) {
  // The executable's own process-wide tuning (heap reuse, helper threads
  // giving way), which the libraries leave to their host: cli/process_policy.
  mpr::cli::applyProcessPolicy();
  CLI::App app{
      "mpr: a bit-exact emulator of an Iris-era graphics pipeline (8 stencil bits, 48-bit\n"
      "accumulation, 24-bit depth) and the multi-pass rendering of Diefenbach & Badler."};
  app.require_subcommand(1);
  int exitCode = 0;
  mpr::cli::addGlCommand(app, exitCode);
  mpr::cli::addConformCommand(app, exitCode);
  mpr::cli::addRenderCommand(app, exitCode);
  mpr::cli::addStepCommand(app, exitCode);
  mpr::cli::addTestCommand(app, exitCode);
  mpr::cli::addInfoCommand(app, exitCode);
  mpr::cli::addReferenceCommand(app, exitCode);
  mpr::cli::addAccuracyCommand(app, exitCode);
  // Past `ulimit -f` a write fails with EFBIG (and the output is left as it
  // was) instead of the process being killed half-way through a file.
  std::signal(SIGXFSZ, SIG_IGN);
  // An interrupt (Ctrl-C, SIGTERM) while files are written removes the
  // temporaries and half-made page folders before the process ends by the
  // signal (util/signal_cleanup): earlier outputs stay as they were.
  mpr::installSignalCleanup();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  } catch (const std::bad_alloc&) {
    // The commands check sizes before allocating; this is the last line
    // (a memory limit below what a checked size needs): no abort, no output.
    std::cerr << "mpr: out of memory (the input needs more memory than this process may use)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "mpr: " << e.what() << "\n";
    return 1;
  }
  return exitCode;
}
