#pragma once
// `mpr render [SCENE] [-o OUT] ...`: render a scene file (or the embedded
// default scene) through the emulated pipeline.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addRenderCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
