#include "algorithms/scene_renderer.hpp"

namespace mpr {

RenderResult renderScene(const Scene& scene, GLCommandStream& gl,
                         const std::function<void(const RenderProgress&)>& progress, bool cull) {
  RenderResult r;
  r.plan = planRender(scene, cull);
  const std::uint64_t predicted = r.plan.predictedViews();
  r.counts = drawScene(scene, r.plan, gl, [&](const DrawWindowProgress& p) {
    if (progress) progress({p.views, predicted, p.label});
  });
  return r;
}

}  // namespace mpr
