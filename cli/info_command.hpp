#pragma once
// `mpr info [SCENE]`: the render plan of a scene (which passes of the 1994
// paper's Figure 4 it needs) and the predicted pass counts.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addInfoCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
