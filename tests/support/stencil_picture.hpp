#pragma once
// GoogleTest form of framebuffer/stencil_picture.hpp:
//
//     EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
//         .   .   1   1
//         .   2   2   1
//         *   .   .   .
//     )"));
//
// On failure the message shows the expected and stored pictures side by side
// and lists every mismatching pixel with both values.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "framebuffer/stencil_picture.hpp"

namespace mpr::test {

inline ::testing::AssertionResult stencilMatches(const mpr::Framebuffer& fb, int x0, int y0,
                                                 std::string_view picture) {
  const std::string why = stencilPictureMismatch(fb, x0, y0, picture);
  if (why.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << why;
}

// A W x H picture (top row first, as stencilMatches reads it) of the values
// value(x, y) for window x, y: for pictures derived from a rule rather than
// drawn by hand.
template <class Value>
std::string stencilPictureOf(int width, int height, Value value) {
  std::string p = "\n";
  for (int y = height - 1; y >= 0; --y) {
    for (int x = 0; x < width; ++x) p += std::to_string(value(x, y)) + " ";
    p += "\n";
  }
  return p;
}

}  // namespace mpr::test
