#pragma once
// GoogleTest helpers for tests of stencil techniques (MPR::testing): a
// stencil-picture matcher whose failure shows both pictures side by side,
// StencilAt, and buffer comparisons that list mismatched runs with both
// values (after PortableGL's regression tests: the failure explains itself).
//
//   EXPECT_THAT(gl, mpr::testing::StencilAt(8, 8, 129));
//   EXPECT_THAT(gl, mpr::testing::HasStencilPicture(2, 2, R"(
//       .   1
//     129   1)"));
//   EXPECT_TRUE(mpr::testing::stencilBuffersEqual(expected, gl.framebuffer()));
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/stencil_picture.hpp"
#include "pipeline/gl/gl_context.hpp"

namespace mpr::testing {

inline const Framebuffer& framebufferOf(const Framebuffer& fb) { return fb; }
inline const Framebuffer& framebufferOf(const GLContext& gl) { return gl.framebuffer(); }

// Matches a GLContext or a Framebuffer whose stencil region with bottom-left
// pixel (x0, y0) matches `picture` (rows top-down, `.` 0, `*` any value).
MATCHER_P3(HasStencilPicture, x0, y0, picture,
           "has the stencil picture at (" + std::to_string(x0) + "," + std::to_string(y0) + ")") {
  const std::string report = stencilPictureMismatch(framebufferOf(arg), x0, y0, picture);
  if (report.empty()) return true;
  *result_listener << "\n" << report;
  return false;
}

// Matches a GLContext or a Framebuffer whose stencil at (x, y) matches `value`
// (a number or a matcher).
MATCHER_P3(StencilAt, x, y, value, "has a stencil at (" + std::to_string(x) + "," + std::to_string(y) + ") that " +
                                       ::testing::DescribeMatcher<unsigned>(value)) {
  const Framebuffer& fb = framebufferOf(arg);
  if (x < 0 || y < 0 || x >= fb.width() || y >= fb.height()) {
    *result_listener << "(" << x << "," << y << ") is outside the " << fb.width() << "x" << fb.height() << " window";
    return false;
  }
  const unsigned stored = fb.stencil(x, y);
  *result_listener << "whose stencil at (" << x << "," << y << ") is " << stored;
  return ::testing::Matches(::testing::Matcher<unsigned>(value))(stored);
}

// Every pixel of the two buffers alike; otherwise the mismatched runs (along
// a row, bottom row first), each with both values, at most `maxRuns` of them.
::testing::AssertionResult stencilBuffersEqual(const Framebuffer& expected, const Framebuffer& actual,
                                               std::size_t maxRuns = 20);
::testing::AssertionResult depthBuffersEqual(const Framebuffer& expected, const Framebuffer& actual,
                                             std::size_t maxRuns = 20);
::testing::AssertionResult colorBuffersEqual(const Framebuffer& expected, const Framebuffer& actual,
                                             std::size_t maxRuns = 20);

}  // namespace mpr::testing
