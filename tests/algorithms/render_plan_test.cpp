// The planner and the recursion's counts: with culling off the recursion
// draws exactly the views the planner predicts (1994 eq. 5 per level), with
// culling on never more; a scene pays only for the effects it uses.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

struct Rendered {
  RenderResult result;
  std::string trace;
  std::vector<Rgba8> color;
};

Rendered render(const Scene& scene, bool cull) {
  GLContext gl(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
  GLCommandStream stream(gl, true);
  Rendered r;
  r.result = renderScene(scene, stream, {}, cull);
  r.trace = stream.trace();
  r.color = gl.framebuffer().colorData();
  EXPECT_EQ(stream.glErrors(), 0u) << scene.file;
  return r;
}

const std::vector<std::string> kSmall = {"render.width=48", "render.height=36"};

class SampleScene : public ::testing::TestWithParam<const char*> {};

TEST_P(SampleScene, CullingOffDrawsExactlyThePredictedPasses) {
  std::vector<std::string> sets = kSmall;
  if (std::string(GetParam()) == "hall_of_mirrors") sets.push_back("render.recursion_depth=3");
  const Scene scene = loadSceneFile(std::string(MPR_SOURCE_DIR) + "/scenes/" + GetParam() + ".yaml", sets);
  const Rendered off = render(scene, false);
  const RenderPlan& p = off.result.plan;
  EXPECT_EQ(off.result.counts.views, p.predictedViews());
  for (int l = 0; l <= p.recursionDepth; ++l)
    EXPECT_EQ(static_cast<std::uint64_t>(off.result.counts.viewsAtLevel[static_cast<std::size_t>(l)]),
              p.predictedViewsAtLevel(l))
        << "level " << l;
  EXPECT_EQ(off.result.counts.lightPasses, p.predictedLightPasses());
  EXPECT_EQ(off.result.counts.shadowPasses, p.predictedShadowPasses());
  EXPECT_EQ(off.result.counts.facesSkipped, 0u);

  const Rendered on = render(scene, true);
  EXPECT_LE(on.result.counts.views, p.predictedViews());
  EXPECT_LE(on.result.counts.lightPasses, p.predictedLightPasses());
  EXPECT_LE(on.result.counts.shadowPasses, p.predictedShadowPasses());
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleScene,
                         ::testing::Values("default", "hall_of_mirrors", "refraction_plate", "soft_shadows",
                                           "frosted_glass", "bathroom"));

TEST(RenderPlan, PaperEquationFiveByHand) {
  RenderPlan p;
  p.reflections = true;
  p.refFaces = 3;
  p.recursionDepth = 3;
  // n (n - 1)^(d - 1): 3, 3 * 2, 3 * 4
  EXPECT_EQ(p.predictedViewsAtLevel(0), 1u);
  EXPECT_EQ(p.predictedViewsAtLevel(1), 3u);
  EXPECT_EQ(p.predictedViewsAtLevel(2), 6u);
  EXPECT_EQ(p.predictedViewsAtLevel(3), 12u);
  EXPECT_EQ(p.predictedViews(), 22u);
  p.lights = 2;
  p.shadows = true;
  p.shadowDepth = 1;
  // Shadowed views (levels 0 and 1) draw their faces' own colours with a
  // shadow and a lit pass per light (bug 4): the faces of level 0 and 1
  // views are the views of levels 1 and 2, 3 + 6.
  EXPECT_EQ(p.predictedShadowPasses(), (1u + 3u) * 2u + (3u + 6u) * 2u);
  EXPECT_EQ(p.predictedLightPasses(), 22u * 2u + (3u + 6u) * 2u);
  p.lightBounces = 3;  // eq. (7)'s d: the depth of the light's reflections
  EXPECT_DOUBLE_EQ(p.paperEq7ShadowGenerations(), 3.0 * (9 + 9) / 2.0 + 1.0);
  EXPECT_DOUBLE_EQ(p.paperEq8Images(), 28.0);
}

// A scene without mirrors renders the same trace and bytes whether or not
// reflections are switched on; one without shadow casters likewise for shadows.
TEST(RenderPlan, SwitchingOffAnUnusedEffectChangesNothing) {
  const std::string base = R"(
camera: {position: [0, 1, 4], look_at: [0, 0.5, 0]}
lights: [{position: [1, 3, 2]}]
materials: {m: {diffuse: [0.7, 0.6, 0.5]}}
objects:
  - {primitive: plane, scale: [4, 1, 4], material: m}
  - {primitive: quad, translate: [0, 1, -1], material: m}
render: {width: 40, height: 30}
)";
  const Scene plain = loadSceneText(base, "s.yaml");
  const Rendered a = render(plain, true);
  EXPECT_FALSE(a.result.plan.reflections);
  EXPECT_FALSE(a.result.plan.shadows);  // quads and planes cast no shadow by default
  for (const char* off : {"render.reflections=false", "render.shadows=false", "render.refractions=false",
                          "render.recursion_depth=0"}) {
    const Rendered b = render(loadSceneText(base, "s.yaml", {off}), true);
    EXPECT_EQ(a.trace, b.trace) << off;
    EXPECT_EQ(a.color, b.color) << off;
  }
  // And no stencil test at all: nothing to mask.
  EXPECT_EQ(a.trace.find("GL_STENCIL_TEST"), std::string::npos);
}

TEST(RenderPlan, InfoNamesWhatWasLeftOut) {
  const Scene s = loadSceneText("lights: []\nobjects: [{primitive: box}]\n", "s.yaml");
  const RenderPlan p = planRender(s);
  const std::string text = describePlan(p, s);
  EXPECT_NE(text.find("no mirror or refracting faces"), std::string::npos) << text;
  EXPECT_NE(text.find("no lights"), std::string::npos) << text;
  EXPECT_EQ(p.predictedViews(), 1u);
}

}  // namespace
}  // namespace mpr
