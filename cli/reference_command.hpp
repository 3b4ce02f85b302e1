#pragma once
// `mpr reference [SCENE] -o OUT ...`: trace a scene file (or the embedded
// default scene) with the reference ray tracer (reference/), the yardstick
// `mpr accuracy` measures the pipeline against.
#include <CLI/CLI.hpp>

namespace mpr::cli {

void addReferenceCommand(CLI::App& app, int& exitCode);

}  // namespace mpr::cli
