#pragma once
// `mpr accuracy`: what accuracy costs in time. The pipeline renders a sweep
// of settings; each is timed and measured against the ray-traced reference.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addAccuracyCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
