// What a sweep renders: one key at a time around the scene, or the product;
// duplicates of the scene's own values left out.
#include "reference/accuracy/sweep.hpp"

#include <gtest/gtest.h>

#include <utility>

#include <stdexcept>

#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

TEST(Sweep, ParsesKeyAndValues) {
  const VaryKey k = parseVary("render.recursion_depth=0,1,2");
  EXPECT_EQ(k.key, "render.recursion_depth");
  EXPECT_EQ(k.values, (std::vector<std::string>{"0", "1", "2"}));
  EXPECT_THROW(parseVary("render.recursion_depth"), std::invalid_argument);
  EXPECT_THROW(parseVary("=1,2"), std::invalid_argument);
  EXPECT_THROW(parseVary("render.shadows="), std::invalid_argument);
  EXPECT_THROW(parseVary("render.recursion_depth=1,,2"), std::invalid_argument);
  EXPECT_THROW(parseVary("render.recursion_depth=1,"), std::invalid_argument);
}

TEST(Sweep, OneKeyAtATimeStartsWithTheScene) {
  const auto s = expandSweep({{"a", {"1", "2"}}, {"b", {"x"}}}, false);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].label(), "scene");
  EXPECT_EQ(s[1].label(), "a=1");
  EXPECT_EQ(s[2].label(), "a=2");
  EXPECT_EQ(s[3].label(), "b=x");
  EXPECT_EQ(s[3].sets(), (std::vector<std::string>{"b=x"}));
}

TEST(Sweep, ProductIsEveryCombination) {
  const auto s = expandSweep({{"a", {"1", "2"}}, {"b", {"x", "y", "z"}}}, true);
  ASSERT_EQ(s.size(), 1u + 6u);
  EXPECT_EQ(s[1].label(), "a=1 b=x");
  EXPECT_EQ(s[6].label(), "a=2 b=z");
}

TEST(Sweep, TheDefaultSweepNamesKeysTheLoaderKnows) {
  for (const VaryKey& k : defaultSweep())
    for (const std::string& v : k.values)
      EXPECT_NO_THROW(loadSceneText(defaultSceneText(), "<default>", {k.key + "=" + v})) << k.key << "=" << v;
}

// A swept value other than the scene's own is a different scene to the
// fingerprint (a key it leaves out would make every value of it a
// "duplicate" of the scene, silently dropped from the sweep).
TEST(Sweep, EverySweptValueMovesTheFingerprint) {
  const Scene base = loadSceneText(defaultSceneText(), "<default>");
  for (const VaryKey& k : defaultSweep())
    for (const std::string& v : k.values) {
      const Scene s = loadSceneText(defaultSceneText(), "<default>", {k.key + "=" + v});
      ASSERT_TRUE(sceneValue(s, k.key)) << k.key;
      if (*sceneValue(base, k.key) == *sceneValue(s, k.key)) continue;
      EXPECT_NE(sceneFingerprint(base), sceneFingerprint(s)) << k.key << "=" << v;
    }
}

// Keys outside the default sweep too: the lens, a light, a material's
// roughness, an object's subdivisions and place (the whole mesh counts).
TEST(Sweep, OtherKeysMoveTheFingerprint) {
  const Scene base = loadSceneText(defaultSceneText(), "<default>");
  for (const char* set : {"camera.aperture=0.1", "camera.focal_distance=3", "materials.floor.roughness=0.2",
                          "lights=[{position: [0, 3.2, 1.5], radius: 0.3}]"})
    EXPECT_NE(sceneFingerprint(base), sceneFingerprint(loadSceneText(defaultSceneText(), "<default>", {set}))) << set;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"subdivisions: 8", "subdivisions: 6"},
                                 {"translate: [-1.0, 0.5, 0.2]", "translate: [-1.0, 0.5, 0.21]"}}) {
    std::string text = defaultSceneText();
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
    EXPECT_NE(sceneFingerprint(base), sceneFingerprint(loadSceneText(text, "<default>"))) << to;
  }
}

// The default scene has recursion_depth 2: that value loads to the scene
// itself, and the fingerprint says so; 3 does not.
TEST(Sweep, TheScenesOwnValueIsTheSameScene) {
  const Scene base = loadSceneText(defaultSceneText(), "<default>");
  const Scene same = loadSceneText(defaultSceneText(), "<default>", {"render.recursion_depth=2"});
  const Scene other = loadSceneText(defaultSceneText(), "<default>", {"render.recursion_depth=3"});
  const Scene moved = loadSceneText(defaultSceneText(), "<default>", {"camera.fov=50"});
  EXPECT_EQ(sceneFingerprint(base), sceneFingerprint(same));
  EXPECT_NE(sceneFingerprint(base), sceneFingerprint(other));
  EXPECT_NE(sceneFingerprint(base), sceneFingerprint(moved));
  EXPECT_EQ(*sceneValue(base, "render.recursion_depth"), "2");
  EXPECT_EQ(*sceneValue(base, "render.refraction_map"), "projection");
  EXPECT_EQ(*sceneValue(base, "render.shadows"), "true");
  EXPECT_EQ(*sceneValue(moved, "camera.fov"), "50");
  // The soft-shadow method is a setting of its own (a sweep over it is not
  // folded into the scene's row).
  const Scene levels = loadSceneText(defaultSceneText(), "<default>", {"render.soft_shadow_method=darkness_levels"});
  EXPECT_NE(sceneFingerprint(base), sceneFingerprint(levels));
  EXPECT_EQ(*sceneValue(base, "render.soft_shadow_method"), "images");
  EXPECT_EQ(*sceneValue(levels, "render.soft_shadow_method"), "darkness_levels");
  EXPECT_FALSE(sceneValue(base, "ambient").has_value());
}

TEST(Sweep, TheSinglePassBaselineTurnsEveryEffectOff) {
  const Scene s = loadSceneText(defaultSceneText(), "<default>", singlePassSets());
  EXPECT_FALSE(s.render.shadows);
  EXPECT_FALSE(s.render.reflections);
  EXPECT_FALSE(s.render.refractions);
  EXPECT_FALSE(s.render.translucency);
  EXPECT_FALSE(s.render.frosted);
}

}  // namespace
}  // namespace mpr
