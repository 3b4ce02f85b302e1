#include "cli/info_command.hpp"

#include <iostream>
#include <memory>

#include "algorithms/render_plan.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::cli {
namespace {

struct InfoOptions {
  std::string scene;
  std::vector<std::string> sets;
  bool noCull = false;
};

int runInfo(const InfoOptions& o) {
  Scene scene;
  try {
    scene = o.scene.empty() ? loadSceneText(defaultSceneText(), "<default scene>", o.sets)
                            : loadSceneFile(o.scene, o.sets);
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::cout << describePlan(planRender(scene, !o.noCull), scene);
  return 0;
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* c = app.add_subcommand("info", "Print a scene's render plan and its predicted pass counts");
  c->footer("The counts are exact for culling off (mpr render --no-cull); `mpr render --stats` reports the actual ones.");
  c->add_option("scene", o->scene, "scene file (YAML); none describes the default scene");
  c->add_option("--set", o->sets, "override a scene value: key.path=value (repeatable)");
  c->add_flag("--no-cull", o->noCull, "plan without face culling");
  c->callback([o, &exitCode] { exitCode = runInfo(*o); });
}

}  // namespace mpr::cli
