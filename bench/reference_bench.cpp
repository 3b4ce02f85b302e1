// Rays per second of the reference ray tracer on the default scene at a
// small size (items = camera + specular + shadow rays).
#include <benchmark/benchmark.h>

#include "reference/reference_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace {

void BM_ReferenceDefaultScene(benchmark::State& state) {
  const mpr::Scene scene =
      mpr::loadSceneText(mpr::defaultSceneText(), "<default scene>", {"render.width=160", "render.height=120"});
  mpr::ReferenceOptions o;
  o.samplesPerPixel = 4;
  o.threads = static_cast<int>(state.range(0));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const mpr::ReferenceImage image = mpr::renderReference(scene, o);
    rays += image.stats.cameraRays + image.stats.specularRays + image.stats.shadowRays;
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(rays));
}
BENCHMARK(BM_ReferenceDefaultScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
