// Hard cases of issue 5: the eye inside a shadow volume, the deepest recursion
// the stencil bits allow between facing mirrors (and a clear refusal one level
// deeper), the camera on and very near a mirror's plane, more nested shadow
// volumes than the stencil can count, an open mesh casting a shadow.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

struct Outcome {
  RenderResult result;
  std::uint8_t maxStencilBelowShadMin = 0;
  std::uint64_t glErrors = 0;
};

// Renders and records, over every pass end, the largest stencil value below SHAD_MIN.
Outcome render(const Scene& scene, GLContext& gl) {
  GLCommandStream stream(gl, false);
  Outcome run;
  stream.onPassEnd([&](const std::string&) {
    for (std::uint8_t v : gl.framebuffer().stencilData())
      if (v < 128) run.maxStencilBelowShadMin = std::max(run.maxStencilBelowShadMin, v);
  });
  run.result = renderScene(scene, stream);
  run.glErrors = stream.glErrors();
  return run;
}

// The wall and box of the canonical scene (draw_window_test.cpp), the camera
// placed between the box and the wall, inside the box's shadow volume, looking
// at the wall: every pixel sees shadowed wall. z-pass would count nothing
// there (no volume face lies between the eye and the wall); z-fail counts
// the volume's far side behind the wall.
TEST(HardCases, EyeInsideAShadowVolumeUsesZFail) {
  const Scene scene = loadSceneText(R"(
camera: {position: [-2, 0, -3.8], look_at: [-2, 0, -5], fov: 90, near: 0.05, far: 20}
lights: [{position: [-2, 0, -3]}]
objects:
  - {primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {primitive: box, translate: [-2, 0, -3.375], scale: [0.5, 0.5, 0.25]}
render: {width: 8, height: 8}
)", "inside.yaml");
  GLContext gl(8, 8, indigoProfile());
  GLCommandStream stream(gl, false);
  std::vector<std::uint8_t> counted;
  stream.onPassEnd([&](const std::string& label) {
    if (label.find("make_all_shadows") != std::string::npos) counted = gl.framebuffer().stencilData();
  });
  const RenderResult r = renderScene(scene, stream);
  EXPECT_EQ(r.counts.zfailVolumes, 1u);
  ASSERT_EQ(counted.size(), 64u);
  for (std::size_t i = 0; i < counted.size(); ++i) EXPECT_EQ(counted[i], 193) << "pixel " << i;
  // The lit pass added nothing: every pixel stays ambient.
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(gl.colorAt(x, y), gl.colorAt(0, 0));
}

// Two facing mirrors, the camera between them looking at one: each view sees
// the other mirror (they are large enough to fill the view at every level), so
// the recursion goes as deep as asked. 127 is the
// deepest level below SHAD_MIN for 8 stencil bits.
constexpr const char* kFacingMirrors = R"(
camera: {position: [0, 0, 0.5], look_at: [0, 0, -1], fov: 60, near: 0.01, far: 1000}
lights: [{position: [0, 0.5, 0]}]
materials: {mirror: {kind: mirror, reflectance: 0.95}, grey: {diffuse: [0.5, 0.5, 0.5]}}
objects:
  - {name: far mirror, primitive: quad, translate: [0, 0, -1], scale: [2000, 2000, 1], material: mirror}
  - {name: near mirror, primitive: quad, translate: [0, 0, 1], rotate: [180, 0, 1, 0], scale: [2000, 2000, 1], material: mirror}
  - {name: floor, primitive: plane, translate: [0, -0.5, 0], scale: [4, 1, 4], material: grey}
render: {width: 16, height: 16, recursion_depth: 127, shadows: false}
)";

TEST(HardCases, DeepestRecursionBetweenFacingMirrors) {
  const Scene scene = loadSceneText(kFacingMirrors, "mirrors.yaml");
  GLContext gl(16, 16, indigoProfile());
  const Outcome run = render(scene, gl);
  EXPECT_EQ(run.glErrors, 0u);
  EXPECT_EQ(run.result.counts.views, 128u);  // one view per level: 0..127
  EXPECT_EQ(run.maxStencilBelowShadMin, 127);
  for (std::uint8_t v : gl.framebuffer().stencilData()) EXPECT_EQ(v, 0);  // every level popped back
}

TEST(HardCases, OneLevelDeeperIsRefused) {
  std::string text = kFacingMirrors;
  text.replace(text.find("recursion_depth: 127"), 20, "recursion_depth: 128");
  try {
    loadSceneText(text, "mirrors.yaml");
    FAIL() << "recursion depth 128 accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("the deepest is 127"), std::string::npos) << e.what();
  }
}

// The camera exactly in the far mirror's plane sees it edge-on (culled:
// nothing to reflect); a hair in front of it, the mirror fills the view.
TEST(HardCases, CameraOnAndNearTheMirrorPlane) {
  for (const char* z : {"-1", "-0.999", "-0.99999"}) {
    std::string text = kFacingMirrors;
    text.replace(text.find("position: [0, 0, 0.5]"), 21, std::string("position: [0, 0, ") + z + "]");
    text.replace(text.find("look_at: [0, 0, -1]"), 19, "look_at: [0, 0, -5]");
    text.replace(text.find("near: 0.01"), 10, "near: 1e-6");
    text.replace(text.find("recursion_depth: 127"), 20, "recursion_depth: 3");
    const Scene scene = loadSceneText(text, "near.yaml");
    GLContext gl(16, 16, indigoProfile());
    const Outcome run = render(scene, gl);
    EXPECT_EQ(run.glErrors, 0u) << z;
    for (std::uint8_t v : gl.framebuffer().stencilData()) EXPECT_EQ(v, 0) << z;
    EXPECT_EQ(run.result.counts.viewsAtLevel[1], std::string(z) == "-1" ? 0 : 1) << z;
  }
}

// 70 thin stacked boxes between a light and a wall: 70 volumes enclose the
// wall's centre, more than the 63 counts between SHAD_ZERO and 255. INCR
// saturates (never wraps into the recursion levels) and the render says so.
TEST(HardCases, MoreNestedVolumesThanTheStencilCountsIsReported) {
  // The camera looks past the stack at the wall, where all 70 shadows overlap.
  std::string text = R"(
camera: {position: [0.9, 0, -1], look_at: [0.3, 0, -4], fov: 20, near: 0.05, far: 20}
lights: [{position: [0, 0, -1]}]
objects:
  - {primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
)";
  for (int i = 0; i < 70; ++i)
    text += "  - {primitive: box, translate: [0, 0, " + std::to_string(-1.5 - 0.0004 * i) + "], scale: [0.2, 0.2, 0.0002]}\n";
  text += "render: {width: 8, height: 8}\n";
  const Scene scene = loadSceneText(text, "many.yaml");
  GLContext gl(8, 8, indigoProfile());
  const Outcome run = render(scene, gl);
  ASSERT_FALSE(run.result.counts.warnings.empty());
  EXPECT_NE(run.result.counts.warnings.front().find("63 or more shadow volumes"), std::string::npos)
      << run.result.counts.warnings.front();
  EXPECT_EQ(run.maxStencilBelowShadMin, 0);  // the counts never fell into the recursion levels
}

TEST(HardCases, OpenMeshCastingAShadowIsWarnedAndRenders) {
  const Scene scene = loadSceneText(R"(
lights: [{position: [0, 3, 0]}]
objects:
  - {primitive: plane, scale: [4, 1, 4]}
  - {name: sheet, primitive: quad, translate: [0, 1, 0], rotate: [-90, 1, 0, 0], casts_shadows: true}
render: {width: 16, height: 12}
)", "open.yaml");
  GLContext gl(16, 12, indigoProfile());
  const Outcome run = render(scene, gl);
  ASSERT_EQ(run.result.counts.warnings.size(), 1u);
  EXPECT_NE(run.result.counts.warnings[0].find("'sheet'"), std::string::npos);
  EXPECT_NE(run.result.counts.warnings[0].find("not a closed mesh"), std::string::npos);
  EXPECT_EQ(run.glErrors, 0u);
}

}  // namespace
}  // namespace mpr
