#include "algorithms/scene_renderer.hpp"

#include "scene/tessellation.hpp"

namespace mpr {

RenderResult renderScene(const Scene& modelled, GLCommandStream& gl,
                         const std::function<void(const RenderProgress&)>& progress, bool cull) {
  // render.tessellation: lit faces split for per-vertex lighting, on a copy
  // (the scene as modelled is what the reference traces).
  Scene tessellated;
  if (modelled.render.tessellation > 0.0f) {
    tessellated = modelled;
    tessellateLitObjects(tessellated, modelled.render.tessellation);
  }
  const Scene& scene = modelled.render.tessellation > 0.0f ? tessellated : modelled;
  RenderResult r;
  r.plan = planRender(scene, cull);
  const std::uint64_t predicted = r.plan.predictedViews();
  r.counts = drawScene(scene, r.plan, gl, [&](const DrawWindowProgress& p) {
    if (progress) progress({p.views, predicted, p.label});
  });
  return r;
}

}  // namespace mpr
