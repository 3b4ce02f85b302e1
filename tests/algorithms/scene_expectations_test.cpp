// A scene's expect: list: which pass labels an entry names, the stencil
// levels the loader resolves (the same as algorithms/stencil_levels.hpp's for
// every profile), and the watcher reading the buffers at the pass.
#include <gtest/gtest.h>

#include <string>

#include "algorithms/scene_expectations.hpp"
#include "algorithms/scene_renderer.hpp"
#include "algorithms/stencil_levels.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

SceneExpectation entry(const std::string& after, int level = -1, int light = -1) {
  SceneExpectation e;
  e.after = after;
  e.level = level;
  e.light = light;
  return e;
}

constexpr const char* kShadowPass =
    "draw_window level 0 > light 0 > draw_all_shadows > shadow volumes | make_all_shadows(ALWAYS)";
constexpr const char* kNestedPass =
    "draw_window level 0 > draw_ref_objects level 1 > face 2 \"mirror\" > draw_window level 1 > light 1 > "
    "draw_all_shadows > shadow volumes | make_all_shadows(ALWAYS)";
constexpr const char* kLevel1Ambient =
    "draw_window level 0 > draw_ref_objects level 1 > face 2 \"mirror\" > draw_window level 1 > ambient | "
    "draw_normal_objects(Camera, ZERO)  // ambient only";

TEST(SceneExpectations, PassLabelsByTextLevelAndLight) {
  EXPECT_TRUE(passMatches(entry("draw_all_shadows > shadow volumes"), kShadowPass));
  EXPECT_TRUE(passMatches(entry("make_all_shadows(ALWAYS)"), kShadowPass));
  EXPECT_FALSE(passMatches(entry("draw_all_shadow > shadow volume"), kShadowPass));
  EXPECT_TRUE(passMatches(entry("shadow volumes", 0, 0), kShadowPass));
  EXPECT_FALSE(passMatches(entry("shadow volumes", 1), kShadowPass));
  EXPECT_FALSE(passMatches(entry("shadow volumes", -1, 1), kShadowPass));
  // The innermost draw_window and its light loop count, not the outer ones.
  EXPECT_TRUE(passMatches(entry("shadow volumes", 1, 1), kNestedPass));
  EXPECT_FALSE(passMatches(entry("shadow volumes", 0), kNestedPass));
  EXPECT_FALSE(passMatches(entry("shadow volumes", -1, 0), kNestedPass));
  // "light 0 added" in the pseudo-code is no light loop; a level 1 ambient
  // pass runs in no light loop.
  EXPECT_FALSE(passMatches(entry("lit", -1, 0), "draw_window level 0 > lit | draw_normal_objects(Camera, ZERO)  // light 0 added"));
  EXPECT_FALSE(passMatches(entry("ambient", 1, 0), kLevel1Ambient));
  EXPECT_TRUE(passMatches(entry("ambient", 1), kLevel1Ambient));
  // after: end is the finished render, never a pass.
  EXPECT_FALSE(passMatches(entry("end"), "accumulate | image 1 of 2: glAccum(GL_ACCUM, 1/2) blend"));
}

constexpr const char* kExpectationsScene = R"(
camera: {position: [0, 0, 0], look_at: [0, 0, -1], up: [0, 1, 0], fov: 90, near: 0.1, far: 20}
lights:
  - {position: [-2, 0, -3]}
objects:
  - {name: wall, primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
  - {name: box, primitive: box, translate: [-2, 0, -3.375], scale: [0.5, 0.5, 0.25]}
render: {width: 16, height: 16, profile: PROFILE}
expect:
  - {after: end, stencil: [0, 0], value: ZERO}
  - {after: end, stencil: [0, 0], value: SHAD_MIN}
  - {after: end, stencil: [0, 0], value: SHAD_ZERO - 2}
  - {after: end, stencil: [0, 0], value: MAX}
  - {after: end, stencil: [0, 0], value: 7}
)";

Scene sceneFor(const std::string& profile) {
  std::string text = kExpectationsScene;
  text.replace(text.find("PROFILE"), 7, profile);
  return loadSceneText(text, "e.yaml");
}

TEST(SceneExpectations, StencilLevelsAreTheAlgorithmsForEveryProfile) {
  for (const std::string& name : profileNames()) {
    const Scene s = sceneFor(name);
    const StencilLevels lv = stencilLevelsFor(*findProfile(name));
    ASSERT_EQ(s.expectations.size(), 5u);
    EXPECT_EQ(s.expectations[0].probe.expected[0], lv.zero) << name;
    EXPECT_EQ(s.expectations[1].probe.expected[0], lv.shadMin) << name;
    EXPECT_EQ(s.expectations[2].probe.expected[0], lv.shadZero - 2) << name;
    EXPECT_EQ(s.expectations[3].probe.expected[0], lv.max) << name;
    EXPECT_EQ(s.expectations[4].probe.expected[0], 7) << name;
    EXPECT_EQ(s.expectations[2].probe.expectedName, "SHAD_ZERO - 2");
    EXPECT_EQ(s.expectations[4].probe.expectedName, "");
    EXPECT_EQ(s.expectations[2].line, 12);  // line 1 is the raw string's empty first line
  }
}

TEST(SceneExpectations, TheWatcherReadsThePassItNames) {
  Scene s = loadSceneText(std::string(kExpectationsScene).replace(std::string(kExpectationsScene).find("PROFILE"), 7, "indigo") +
                              "  - {after: \"draw_all_shadows > shadow volumes\", light: 0, stencil: [4, 7], value: SHAD_ZERO + 1}\n"
                              "  - {after: \"back to ZERO\", stencil: all, value: ZERO}\n",
                          "e.yaml");
  GLContext gl(16, 16, *findProfile("indigo"));
  GLCommandStream stream(gl, false);
  SceneExpectationWatcher w(s, stream, gl);
  renderScene(s, stream);
  w.finish();
  ASSERT_EQ(w.outcomes().size(), 7u);
  EXPECT_TRUE(w.unmatched().empty());
  const ExpectationOutcome& shadow = w.outcomes()[5];
  EXPECT_TRUE(shadow.evaluated);
  EXPECT_TRUE(shadow.probe.passed) << shadow.probe.message;
  EXPECT_EQ(shadow.passLabel, kShadowPass);
  EXPECT_TRUE(w.outcomes()[6].probe.passed) << w.outcomes()[6].probe.message;
  // At the end the stencil is ZERO: SHAD_MIN, SHAD_ZERO - 2, MAX and 7 do
  // not hold; the first of them in the render's order is the file's first.
  EXPECT_TRUE(w.outcomes()[0].probe.passed);
  EXPECT_EQ(w.firstFailure(), 1);
  EXPECT_EQ(w.outcomes()[2].probe.message, "stencil at (0,0): expected SHAD_ZERO - 2 = 190, found 0");
  EXPECT_EQ(expectationText(s.expectations[5]),
            "after \"draw_all_shadows > shadow volumes\", light 0: stencil SHAD_ZERO + 1 = 193 at (4,7)");
  EXPECT_EQ(w.passes(), 8);  // clear, ambient, render area, shadow volumes, count check, lit, reset, back to ZERO
}

}  // namespace
}  // namespace mpr
