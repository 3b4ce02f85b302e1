#pragma once
// Stencil regions as ASCII pictures, for tests a person can read:
//
//     .   .   1   1
//     .   2   2   1
//     *   .   .   .
//
// Rows are written top to bottom (the highest window y first), tokens are
// separated by blanks: a decimal value, `.` for 0, or `*` for "any value".
#include <string>
#include <string_view>

#include "framebuffer/framebuffer.hpp"

namespace mpr {

// The stencil values of `region` as a picture in the format above.
std::string stencilPicture(const Framebuffer& fb, const PixelRect& region);

// Compares the region whose bottom-left pixel is (x0, y0) with `picture`.
// Returns an empty string when every pixel matches, otherwise a report with
// the expected and actual pictures and each mismatching pixel with both values.
// A malformed picture (ragged rows, bad tokens, outside the window) is reported
// the same way.
std::string stencilPictureMismatch(const Framebuffer& fb, int x0, int y0, std::string_view picture);

}  // namespace mpr
