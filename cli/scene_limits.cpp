#include "cli/scene_limits.hpp"

#include <charconv>
#include <limits>
#include <system_error>

#include "algorithms/light_path.hpp"
#include "util/saturating.hpp"

namespace mpr::cli {

CLI::Validator wholeNumberFrom(std::uint64_t least) {
  // Checked on the text: CLI11 reads "-1" into an unsigned option as its
  // wrapped value and a number past 2^64 - 1 as the largest, both accepted.
  return CLI::Validator(
      [least](std::string& text) -> std::string {
        std::uint64_t v = 0;
        const char* end = text.data() + text.size();
        const auto [p, ec] = std::from_chars(text.data(), end, v);
        if (text.empty() || ec != std::errc() || p != end || v < least)
          return "must be a whole number from " + std::to_string(least) + " to " + std::to_string(std::numeric_limits<std::uint64_t>::max()) +
                 ", not '" + text + "'";
        return "";
      },
      std::to_string(least) + "..2^64-1");
}

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
      ->check(wholeNumberFrom(1));
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
    if (p.passes > max) throw PassLimitReached{p.passes};
    if (then) then(p);
  };
}

std::string passLimitMessage(const Scene& scene, const PassLimitReached& stop, const SceneLimits& limits) {
  return scene.file + ": the render passed --max-passes " + std::to_string(limits.maxPasses) + " at pass " +
         std::to_string(stop.passes) + " (views, lit and shadow passes; the plan allows up to " +
         countText(planRender(scene, true).predictedPasses()) + ")";
}

}  // namespace mpr::cli
