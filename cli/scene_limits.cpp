#include "cli/scene_limits.hpp"

#include <limits>

#include "algorithms/light_path.hpp"
#include "util/saturating.hpp"

namespace mpr::cli {

void addConfineOption(CLI::App& command, SceneLimits& limits) {
  command.add_flag("--confine", limits.confine,
                   "refuse mesh files outside the scene's folder (absolute paths, '..', links out), for scenes "
                   "someone else wrote");
}

void addSceneLimitOptions(CLI::App& command, SceneLimits& limits) {
  addConfineOption(command, limits);
  command
      .add_option("--max-passes", limits.maxPasses,
                  "refuse a render of more passes (views, lit and shadow passes; default 1000000)")
      ->check(CLI::Range(std::uint64_t{1}, std::numeric_limits<std::uint64_t>::max()));
}

std::string planLimitProblem(const Scene& scene, const RenderPlan& plan, bool cull, const SceneLimits& limits) {
  if (plan.lightPathsOverLimit)
    return scene.file + ": the lights have more than " + std::to_string(kMaxLightPaths) +
           " paths through the specular faces (render.light_bounces " + std::to_string(plan.lightBounces) +
           "); lower render.light_bounces";
  if (cull || plan.predictedPasses() <= limits.maxPasses) return "";
  return scene.file + ": the render would take " + countText(plan.predictedPasses()) +
         " passes (views, lit and shadow passes; mpr info --no-cull lists them), more than --max-passes " +
         std::to_string(limits.maxPasses);
}

std::function<void(const RenderProgress&)> passLimitWatch(const SceneLimits& limits,
                                                          std::function<void(const RenderProgress&)> then) {
  return [max = limits.maxPasses, then = std::move(then)](const RenderProgress& p) {
    if (p.views > max) throw PassLimitReached{p.views};
    if (then) then(p);
  };
}

std::string passLimitMessage(const Scene& scene, const PassLimitReached& stop, const SceneLimits& limits) {
  return scene.file + ": the render passed --max-passes " + std::to_string(limits.maxPasses) + " at view " +
         std::to_string(stop.views) + " (the plan allows up to " + countText(planRender(scene, true).predictedPasses()) +
         " passes)";
}

}  // namespace mpr::cli
