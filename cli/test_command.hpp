#pragma once
// `mpr test FILE|DIR... [--junit FILE] [--report DIR]`: GL scripts with
// probes run as tests.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addTestCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
