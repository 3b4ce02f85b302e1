#pragma once
// A scene's `expect:` list as a test (`mpr render`, `mpr test SCENE.yaml`):
// the located errors (an `after` no pass matched), or the first expectation
// that does not hold, explained as a failing script probe is: expected and
// found, the pass it was read at, and its first failing pixel's history up
// to there (the render's trace replayed, as `mpr step SCENE --pixel` words it).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/scene_expectations.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene.hpp"

namespace mpr::cli {

struct SceneTestResult {
  std::size_t expectations = 0;
  std::vector<std::string> errors;  // FILE:LINE:COLUMN: ... matched no pass ...
  bool passed = true;               // every expectation evaluated holds
  std::string where;                // the first failure: FILE:LINE: expectationText
  std::string message;              // its explanation and the pass it was read at
  int line = 0;                     // its line in the scene file
  std::string history;              // its first failing pixel's history
  int width = 0, height = 0;
  std::vector<std::uint8_t> difference;  // probeDifferenceImage (RGB, bottom-up)
};

// After the render `watcher` watched (and its finish()); `history`: record
// the failing pixel's history (a second render, with the trace).
SceneTestResult sceneTestResult(const Scene& scene, const SceneExpectationWatcher& watcher, bool history);

// Renders `scene` and checks its expectations; `progress` is renderScene's
// (passLimitWatch stops a render past --max-passes by throwing).
SceneTestResult runSceneTest(const Scene& scene, const std::function<void(const RenderProgress&)>& progress = {});

// The failure as `mpr render` prints it and `mpr test` under its FAIL line:
// the message, then the history, every line after the first indented.
std::string sceneFailureText(const SceneTestResult& r, const std::string& indent);

}  // namespace mpr::cli
