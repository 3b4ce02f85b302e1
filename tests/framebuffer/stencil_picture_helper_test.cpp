// The test helper tests/support/stencil_picture.hpp: orientation (first row
// is the highest y), `.` and `*`, and a failure message that shows both
// pictures and lists every mismatching pixel with both values.
#include <gtest/gtest.h>

#include <string>

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "support/stencil_picture.hpp"

namespace mpr {
namespace {

using test::stencilMatches;

// A 4x3 window; stored values set by hand so that every pixel is distinct
// except the zeros:
//   y = 2:   0   7   0  12
//   y = 1:   0   0 255   0
//   y = 0:   3   0   0   0
Framebuffer sample() {
  Framebuffer fb(4, 3, indigoProfile());
  fb.stencil(1, 2) = 7;
  fb.stencil(3, 2) = 12;
  fb.stencil(2, 1) = 255;
  fb.stencil(0, 0) = 3;
  return fb;
}

TEST(StencilPictureHelper, MatchesWithTopRowHighestY) {
  const Framebuffer fb = sample();
  EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
    .  7   .  12
    .  .  255  .
    3  .   .   .
  )"));
  // Decimal 0 and `.` are the same; tabs separate too.
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "0 7 0 12\n0\t0 255 0\n3 0 0 0"));
  // A sub-region: bottom-left (2, 1), 2x2.
  EXPECT_TRUE(stencilMatches(fb, 2, 1, ". 12\n255 ."));
}

TEST(StencilPictureHelper, DontCareSkipsPixels) {
  const Framebuffer fb = sample();
  EXPECT_TRUE(stencilMatches(fb, 0, 0, "* * * *\n* * 255 *\n3 * * *"));
}

TEST(StencilPictureHelper, UpsideDownPictureFails) {
  const Framebuffer fb = sample();
  EXPECT_FALSE(stencilMatches(fb, 0, 0, "3 . . .\n. . 255 .\n. 7 . 12"));
}

TEST(StencilPictureHelper, FailureShowsBothPicturesAndEveryMismatch) {
  const Framebuffer fb = sample();
  const ::testing::AssertionResult r = stencilMatches(fb, 0, 0, R"(
    .  7   .  12
    .  5  255  .
    4  .   *   .
  )");
  ASSERT_FALSE(r);
  const std::string msg = r.message();
  // Two mismatches: (1,1) expected 5 stored 0; (0,0) expected 4 stored 3.
  EXPECT_NE(msg.find("2 stencil value(s) differ"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(1,1): expected 5, stored 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0,0): expected 4, stored 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected"), std::string::npos) << msg;
  EXPECT_NE(msg.find("stored"), std::string::npos) << msg;
  // The side-by-side row for y = 1, expected on the left, stored on the
  // right, marked as differing (column width 3 = the widest token, "255").
  EXPECT_NE(msg.find("y=1    .   5 255   .   |   .   . 255   .   <<"), std::string::npos) << msg;
  // The row for y = 2 matches and is not marked.
  EXPECT_NE(msg.find("y=2    .   7   .  12   |   .   7   .  12\n"), std::string::npos) << msg;
}

TEST(StencilPictureHelper, MalformedPicturesFail) {
  const Framebuffer fb = sample();
  EXPECT_FALSE(stencilMatches(fb, 0, 0, ""));                     // empty
  EXPECT_FALSE(stencilMatches(fb, 0, 0, ". .\n. . ."));           // ragged
  EXPECT_FALSE(stencilMatches(fb, 0, 0, "3 x . ."));              // bad token
  EXPECT_FALSE(stencilMatches(fb, 0, 0, "256 . . ."));            // not a byte
  EXPECT_FALSE(stencilMatches(fb, 0, 0, "-3 . . ."));             // not a byte
  EXPECT_FALSE(stencilMatches(fb, 2, 2, ". .\n. ."));             // reaches y = 3
  EXPECT_FALSE(stencilMatches(fb, 3, 0, ". ."));                  // reaches x = 4
  EXPECT_FALSE(stencilMatches(fb, -1, 0, ". ."));                 // negative origin
  const std::string why = stencilMatches(fb, 0, 0, "3 x . .").message();
  EXPECT_NE(why.find("'x'"), std::string::npos) << why;
}

}  // namespace
}  // namespace mpr
