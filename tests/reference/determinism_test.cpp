// The reference's bytes depend on nothing but the scene and the options:
// not on the thread count, not on the run.
#include <cstring>

#include "tests/reference/reference_test_support.hpp"

namespace mpr {
namespace {

ReferenceImage traceDefault(int threads) {
  const Scene scene = loadSceneText(defaultSceneText(), "<default scene>", {"render.width=40", "render.height=30"});
  ReferenceOptions o;
  o.samplesPerPixel = 4;
  o.threads = threads;
  return renderReference(scene, o);
}

bool sameBytes(const ReferenceImage& a, const ReferenceImage& b) {
  return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST(Determinism, OneAndTwoThreadsGiveTheSameBytes) {
  const ReferenceImage one = traceDefault(1), two = traceDefault(2), three = traceDefault(3);
  EXPECT_TRUE(sameBytes(one, two));
  EXPECT_TRUE(sameBytes(one, three));
  // The rays are counted whatever the threads.
  EXPECT_EQ(one.stats.cameraRays, 40u * 30u * 4u);
  EXPECT_EQ(one.stats.shadowRays, two.stats.shadowRays);
  EXPECT_EQ(one.stats.specularRays, two.stats.specularRays);
}

TEST(Determinism, TheSameRunTwiceGivesTheSameBytes) {
  EXPECT_TRUE(sameBytes(traceDefault(2), traceDefault(2)));
}

TEST(Determinism, ProgressReachesEveryRow) {
  const Scene scene = loadSceneText(defaultSceneText(), "<default scene>", {"render.width=8", "render.height=6"});
  ReferenceOptions o;
  o.samplesPerPixel = 1;
  int last = 0, calls = 0;
  o.progress = [&](int done, int rows) {
    EXPECT_EQ(rows, 6);
    EXPECT_EQ(done, last + 1);  // serialised, one call a row
    last = done, ++calls;
  };
  renderReference(scene, o);
  EXPECT_EQ(calls, 6);
}

}  // namespace
}  // namespace mpr
