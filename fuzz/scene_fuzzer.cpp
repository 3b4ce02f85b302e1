// The scene loader and the planner: any bytes give a Scene or a SceneError,
// and a loaded scene plans (and describes its plan) without crashing. Mesh
// paths are resolved beside "fuzz/corpus.yaml", where no meshes are.
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/render_plan.hpp"
#include "scene/scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const mpr::Scene scene = mpr::loadSceneText(text, "fuzz/corpus.yaml");
    if (scene.triangleCount() > 200000) return 0;  // keeps one input fast
    for (bool cull : {true, false}) (void)mpr::describePlan(mpr::planRender(scene, cull), scene);
  } catch (const mpr::SceneError&) {
  }
  return 0;
}
