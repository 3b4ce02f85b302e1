#pragma once
// `mpr step INPUT [--pixel X,Y | --state N | --html DIR]`: walk a GL script (or the GL
// calls of a scene's render) pass by pass.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addStepCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
