#pragma once
// --confine and --max-passes, defined once for every command that loads a
// scene (issue 15): a service that renders scenes it did not write bounds
// what a scene may read and how long its render may run.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>

#include "algorithms/render_plan.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene.hpp"

namespace mpr::cli {

struct SceneLimits {
  bool confine = false;              // mesh files only from inside the scene's folder
  std::uint64_t maxPasses = 1000000;  // views, lit and shadow passes one render may take
};

// A whole number from `least` to 2^64 - 1, checked on the option's text,
// for unsigned 64-bit options (--max-passes, conform --seed).
CLI::Validator wholeNumberFrom(std::uint64_t least);

// Adds --confine to `command`.
void addConfineOption(CLI::App& command, SceneLimits& limits);
// Adds --confine and --max-passes to `command` (one that renders through the pipeline).
void addSceneLimitOptions(CLI::App& command, SceneLimits& limits);

// Thrown by passLimitWatch's callback when a render's passes (views, lit
// and shadow passes) pass --max-passes.
struct PassLimitReached {
  std::uint64_t passes;
};

// Why a render of `plan` is refused before it starts, or empty: with
// culling off the plan's count is exact, and past --max-passes it is refused
// (with culling it is an upper bound, and the render is watched instead,
// every view, lit and shadow pass counted as it starts).
std::string planLimitProblem(const Scene& scene, const RenderPlan& plan, bool cull, const SceneLimits& limits);

// A renderScene progress callback that throws PassLimitReached once the
// render's passes (views, lit and shadow passes) pass --max-passes, then
// calls `then` (may be empty).
std::function<void(const RenderProgress&)> passLimitWatch(const SceneLimits& limits,
                                                          std::function<void(const RenderProgress&)> then = {});

// The message for a render stopped by passLimitWatch.
std::string passLimitMessage(const Scene& scene, const PassLimitReached& stop, const SceneLimits& limits);

}  // namespace mpr::cli
