#pragma once
// One setting rendered by the pipeline as `mpr render` renders it, timed, with
// the passes it took (the columns of the 1997 paper's Tables 2 and 3).
#include <cstdint>
#include <functional>
#include <vector>

#include "algorithms/scene_renderer.hpp"
#include "reference/accuracy/image_error.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct PipelineMeasurement {
  double seconds = 0.0;          // median wall time of the runs
  std::vector<double> runs;      // each run's wall time
  std::uint64_t views = 0, lightPasses = 0, shadowPasses = 0, glCalls = 0, fragments = 0;
  Rgb8Image image;               // the colour buffer (the same every run)
};

// Renders `scene` `repeat` times (at least once), each on a fresh context;
// `progress` is renderScene's (mpr accuracy --max-passes stops a render by throwing).
PipelineMeasurement measurePipeline(const Scene& scene, int repeat,
                                    const std::function<void(const RenderProgress&)>& progress = {});

// The planner's cost of `scene` in scene-rendering units: every view's
// ambient pass, its light passes and its shadow-volume passes, predicted with
// culling off (an upper bound on what a render with culling draws).
double predictedPasses(const Scene& scene);

}  // namespace mpr
