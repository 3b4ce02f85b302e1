#pragma once
// `mpr gl SCRIPT [--profile NAME] [--dump DIR]`: run a GL script.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addGlCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
