// mpr: the command-line front end. Thin by design: it parses arguments and
// calls the libraries.
#include <CLI/CLI.hpp>

#include "cli/accuracy_command.hpp"
#include "cli/conform_command.hpp"
#include "cli/gl_command.hpp"
#include "cli/info_command.hpp"
#include "cli/reference_command.hpp"
#include "cli/render_command.hpp"
#include "cli/step_command.hpp"
#include "cli/test_command.hpp"

int main(int argc, char** argv) {
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  return exitCode;
}
