#include "cli/info_command.hpp"

#include <iostream>
#include <memory>

#include "algorithms/render_plan.hpp"
#include "cli/scene_limits.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::cli {
namespace {

struct InfoOptions {
  std::string scene;
  std::vector<std::string> sets;
  bool noCull = false;
  SceneLimits limits;
};

int runInfo(const InfoOptions& o) {
  Scene scene;
  try {
    scene = o.scene.empty() ? loadSceneText(defaultSceneText(), "<default scene>", o.sets)
                            : loadSceneFile(o.scene, o.sets, o.limits.confine);
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  const RenderPlan plan = planRender(scene, !o.noCull);
  std::cout << describePlan(plan, scene);
  // The plan is printed either way; a plan `mpr render` would refuse exits 2.
  if (const std::string problem = planLimitProblem(scene, plan, !o.noCull, o.limits); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  return 0;
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* c = app.add_subcommand("info", "Print a scene's render plan and its predicted pass counts");
  c->footer(
      "The counts are exact for culling off (mpr render --no-cull); `mpr render --stats` reports the actual ones.\n"
      "With --no-cull, a plan of more passes than --max-passes (one mpr render --no-cull would refuse)\n"
      "is printed, then refused on stderr with exit status 2.");
  c->add_option("scene", o->scene, "scene file (YAML); none describes the default scene");
  c->add_option("--set", o->sets, "override a scene value: key.path=value (repeatable)");
  c->add_flag("--no-cull", o->noCull, "plan without face culling");
  addSceneLimitOptions(*c, o->limits);
  c->callback([o, &exitCode] { exitCode = runInfo(*o); });
}

}  // namespace mpr::cli
