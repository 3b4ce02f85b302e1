// A mirror's view is the view from the mirrored camera (1994 paper, §4): a
// change-of-medium pane seen in a mirror must show, pixel for pixel, what
// the mirrored camera sees through it directly, flipped left to right. The
// refracted view inside the mirror's view (its camera turned about the
// pane by Snell's law, its image map M3, its clip plane and near plane)
// must compose with the reflection exactly as the reflection composes with
// the scene. Emission only, no light: the colours do not depend on the view.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/algorithms/rendered_colours.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::glass_in_a_mirror_test {
namespace {

constexpr int kWidth = 96, kHeight = 72;

// Behind the real camera (z = 5, facing the mirror in z = 0): a red and a
// green wall at z = 10 and, before them, a pane of ior 1.5 turned 30 degrees
// from facing the mirror, so what is seen through it is bent sideways.
const char* kBehindTheCamera = R"(
  - {name: red wall, primitive: quad, translate: [-1.5, 0, 10], rotate: [180, 0, 1, 0], scale: [3, 6, 1], material: red}
  - {name: green wall, primitive: quad, translate: [1.5, 0, 10], rotate: [180, 0, 1, 0], scale: [3, 6, 1], material: green}
  - {name: pane, primitive: quad, translate: [0, 0, 7], rotate: [150, 0, 1, 0], scale: [3, 3, 1], material: glass}
)";

std::string scene(const std::string& camera, bool mirror) {
  return std::string("ambient: [0, 0, 0]\nmaterials:\n"
                     "  red:    {diffuse: [0, 0, 0], emission: [0.9, 0.1, 0.1]}\n"
                     "  green:  {diffuse: [0, 0, 0], emission: [0.1, 0.8, 0.2]}\n"
                     "  glass:  {kind: refractive, diffuse: [0, 0, 0], ior: 1.5, transmittance: 1}\n") +
         (mirror ? "  mirror: {kind: mirror, diffuse: [0, 0, 0], reflectance: 1}\n" : "") +
         "render: {width: 96, height: 72, recursion_depth: 3}\ncamera: " + camera + "\nobjects:\n" +
         (mirror ? "  - {name: mirror, primitive: quad, scale: [8, 8, 1], material: mirror}\n" : "") + kBehindTheCamera;
}

std::vector<Rgba8> render(const std::string& text) { return test::renderedColours(text, "glass-in-a-mirror.yaml"); }

TEST(GlassInAMirror, IsTheMirroredCamerasViewThroughIt) {
  // The mirror (8 x 8 at 5, fov 45) fills the window.
  const std::vector<Rgba8> inMirror =
      render(scene("{position: [0, 0, 5], look_at: [0, 0, 0], fov: 45, near: 0.1, far: 50}", true));
  const std::vector<Rgba8> direct =
      render(scene("{position: [0, 0, -5], look_at: [0, 0, 0], fov: 45, near: 0.1, far: 50}", false));
  int off = 0, bent = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Rgba8& a = inMirror[static_cast<std::size_t>(y * kWidth + x)];
      const Rgba8& b = direct[static_cast<std::size_t>(y * kWidth + kWidth - 1 - x)];
      for (int c = 0; c < 3; ++c) off += std::abs(int{a[c]} - int{b[c]}) > 1;
      bent += a[0] > 200;  // red: the red wall, through the pane or beside it
    }
  // Within one step (the two renders round their lighting-free colours
  // through different matrices), and not a trivial picture: the pane moves
  // what is seen through it.
  EXPECT_EQ(off, 0);
  EXPECT_GT(bent, 200);
  std::string noPane = scene("{position: [0, 0, -5], look_at: [0, 0, 0], fov: 45, near: 0.1, far: 50}", false);
  noPane.erase(noPane.find("  - {name: pane"));
  noPane.replace(noPane.find("  glass:"), noPane.find("render:") - noPane.find("  glass:"), "");
  noPane.erase(noPane.find(", recursion_depth: 3"), 20);  // nothing to recurse into: refused without a specular face
  const std::vector<Rgba8> unbent = render(noPane);
  int moved = 0;
  for (std::size_t i = 0; i < direct.size(); ++i) moved += direct[i] != unbent[i];
  EXPECT_GT(moved, 300);
}

}  // namespace
}  // namespace mpr::glass_in_a_mirror_test
