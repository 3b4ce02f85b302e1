// MPR::testing's helpers explain their failures: the mismatched runs with
// both values, the stencil picture side by side, the stencil found.
#include "testing/gtest_helpers.hpp"

#include <GL/gl.h>

namespace mpr::testing {
namespace {

TEST(BufferComparison, ListsMismatchedRunsWithBothValues) {
  Framebuffer a(4, 2, indigoProfile()), b(4, 2, indigoProfile());
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) a.stencil(x, y) = b.stencil(x, y) = 0;
  b.stencil(1, 0) = 5;
  b.stencil(2, 0) = 6;
  b.stencil(3, 1) = 7;
  const ::testing::AssertionResult r = stencilBuffersEqual(a, b);
  EXPECT_FALSE(r);
  EXPECT_STREQ(r.message(),
               "3 stencil pixel(s) differ in 2 run(s)\n"
               "  y=0, x 1..2: expected 0 0, found 5 6\n"
               "  y=1, x 3..3: expected 0, found 7\n");
  EXPECT_TRUE(stencilBuffersEqual(a, a));
}

TEST(StencilMatchers, ExplainWhatTheyFound) {
  GLContext gl(4, 4, indigoProfile());
  gl.clearStencil(3);
  gl.clear(GL_STENCIL_BUFFER_BIT);
  EXPECT_THAT(gl, StencilAt(1, 1, 3u));
  EXPECT_THAT(gl, ::testing::Not(StencilAt(1, 1, 4u)));
  EXPECT_THAT(gl, HasStencilPicture(0, 0, "3 *\n3 3"));
  ::testing::StringMatchResultListener listener;
  EXPECT_FALSE(::testing::ExplainMatchResult(StencilAt(1, 1, 4u), gl, &listener));
  EXPECT_EQ(listener.str(), "whose stencil at (1,1) is 3");
  ::testing::StringMatchResultListener picture;
  EXPECT_FALSE(::testing::ExplainMatchResult(HasStencilPicture(0, 0, "3 ."), gl, &picture));
  EXPECT_NE(picture.str().find("(1,0): expected 0, stored 3"), std::string::npos) << picture.str();
}

}  // namespace
}  // namespace mpr::testing
