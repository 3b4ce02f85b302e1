#pragma once
// The scene of the frosted-light tests, pipeline and reference alike
// (tests/algorithms/frosted_light_test.cpp holds its hand derivation): a
// pane of material `pane` held level 1.5 above a floor under a light at
// (0.3, 3, -0.5), seen from (0, 3.2, 3.2) at 64x48, fov 50.
#include <string>

namespace mpr::test {

inline std::string frostedPaneScene(const std::string& pane) {
  return R"(
camera: {position: [0, 3.2, 3.2], look_at: [0, 0, 0], fov: 50, near: 0.1, far: 20}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [0.3, 3.0, -0.5]}]
materials:
  pane: )" + pane + R"(
objects:
  - {primitive: plane, scale: [6, 1, 6]}
  - {primitive: quad, translate: [0, 1.5, -1.2], rotate: [-90, 1, 0, 0], scale: [1.2, 1.2, 1], material: pane}
render: {width: 64, height: 48}
)";
}

}  // namespace mpr::test
