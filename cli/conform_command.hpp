#pragma once
// `mpr conform SCRIPT [--driver llvmpipe|softpipe] [--report DIR]`: run a GL
// script on MPR and on Mesa (OSMesa) and compare every buffer.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addConformCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
