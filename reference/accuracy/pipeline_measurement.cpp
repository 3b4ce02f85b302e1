#include "reference/accuracy/pipeline_measurement.hpp"

#include <algorithm>
#include <chrono>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/scene_renderer.hpp"

namespace mpr {

PipelineMeasurement measurePipeline(const Scene& scene, int repeat,
                                    const std::function<void(const RenderProgress&)>& progress) {
  PipelineMeasurement m;
  for (int run = 0; run < std::max(1, repeat); ++run) {
    GLContext gl(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
    GLCommandStream stream(gl, false);
    const auto t0 = std::chrono::steady_clock::now();
    const RenderResult r = renderScene(scene, stream, progress);
    m.runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (run > 0) continue;
    m.views = r.counts.views;
    m.lightPasses = r.counts.lightPasses;
    m.shadowPasses = r.counts.shadowPasses;
    m.glCalls = stream.calls();
    m.fragments = gl.counters().fragmentsTested;
    const Framebuffer& fb = gl.framebuffer();
    m.image = {fb.width(), fb.height(), {}};
    m.image.rgb.reserve(3 * fb.colorData().size());
    for (const Rgba8& c : fb.colorData()) m.image.rgb.insert(m.image.rgb.end(), {c[0], c[1], c[2]});
  }
  std::vector<double> sorted = m.runs;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  m.seconds = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  return m;
}

double predictedPasses(const Scene& scene) {
  const RenderPlan p = planRender(scene, false);
  return static_cast<double>(p.predictedViews() + p.predictedLightPasses() + p.predictedShadowPasses());
}

}  // namespace mpr
