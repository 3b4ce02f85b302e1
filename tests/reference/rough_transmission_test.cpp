// Issue 43, defect 10: the reference scatters the light a frosted face
// passes on as it scatters the view through it (1997 §3's rough
// transmission, by reciprocity), where it used to pass it as smooth glass
// does. The scene of tests/algorithms/frosted_light_test.cpp (its
// derivation there): a frosted slab pane held level 1.5 above a floor, the
// light above it, the floor seen directly; its shadow's front edge in rows
// 26..32 blurred by a standard deviation of 0.225, the patch's middle (row
// 36, column 32) 0.9 and more from every edge (4 standard deviations).
#include "tests/reference/reference_test_support.hpp"
#include "tests/algorithms/frosted_pane_scene.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::rough_transmission_test {
namespace {

std::string scene(const std::string& pane) { return test::frostedPaneScene(pane); }

TEST(RoughTransmission, AFrostedPaneScattersTheLightItPasses) {
  const ReferenceImage clear = test::traceText(
      scene("{kind: refractive, diffuse: [0.8, 0.8, 0.8], ior: 1.5, transmittance: 0.8, thickness: 0.008}"), 16);
  const ReferenceImage frosted =
      test::traceText(scene("{kind: frosted, diffuse: [0.8, 0.8, 0.8], ior: 1.5, transmittance: 0.8, "
                            "thickness: 0.008, shear: 0.15, samples: 8, fog_distance: 10}"),
                      16);
  // The middle of the light it passes: as through clear glass (the same
  // pixel samples; the scattered crossings all land on the pane).
  EXPECT_NEAR(test::byteAt(frosted, 32, 36, 0), test::byteAt(clear, 32, 36, 0), 2);
  // The edges blur both ways; the floor directly seen (rows up to 41) is
  // otherwise the same pixel for pixel (the same samples, no other
  // randomness there).
  int darker = 0, brighter = 0;
  for (int y = 0; y <= 41; ++y)
    for (int x = 0; x < 64; ++x) {
      const int d = test::byteAt(frosted, x, y, 0) - test::byteAt(clear, x, y, 0);
      darker += d < -4;
      brighter += d > 4;
    }
  EXPECT_GE(darker, 20);
  EXPECT_GE(brighter, 20);
  RecordProperty("floor pixels darker, brighter", std::to_string(darker) + ", " + std::to_string(brighter));
}

}  // namespace
}  // namespace mpr::rough_transmission_test
