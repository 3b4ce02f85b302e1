#pragma once
// Test helper: compare a rectangle of a Framebuffer's stencil buffer with an
// ASCII picture a person can read and write.
//
//     EXPECT_TRUE(stencilMatches(fb, 0, 0, R"(
//         .   .   1   1
//         .   2   2   1
//         *   .   .   .
//     )"));
//
// Picture format:
//   - rows as written, top to bottom, are window rows from the highest y down
//     to y0 (so the picture looks like the window does on screen);
//   - tokens are separated by blanks (spaces or tabs); blank lines are ignored;
//   - a token is a decimal value (0 ... 255), `.` meaning 0, or `*` meaning
//     "don't care";
//   - (x0, y0) is the window position of the picture's bottom-left token.
//
// On failure the message shows the expected and the stored picture side by
// side (with the window y of every row, mismatching rows marked `<<`) and then
// lists every mismatching pixel with both values. A malformed picture (ragged
// rows, a bad token, a region reaching outside the window) is a failure with
// its reason.
//
// Header-only and self-contained on purpose (only the Framebuffer accessors
// are used), so it can later move into the library unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "framebuffer/framebuffer.hpp"

namespace mpr::test {

namespace stencil_picture_detail {

inline constexpr int kDontCare = -1;

// Splits the picture into rows of tokens; lines holding only blanks are dropped.
inline std::vector<std::vector<std::string>> tokenize(std::string_view picture) {
  std::vector<std::vector<std::string>> rows;
  std::size_t pos = 0;
  while (pos <= picture.size()) {
    std::size_t end = picture.find('\n', pos);
    if (end == std::string_view::npos) end = picture.size();
    const std::string_view line = picture.substr(pos, end - pos);
    std::vector<std::string> row;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
      if (j > i) row.emplace_back(line.substr(i, j - i));
      i = j;
    }
    if (!row.empty()) rows.push_back(std::move(row));
    pos = end + 1;
  }
  return rows;
}

// A token's value: 0 ... 255, kDontCare for `*`, or -2 when malformed.
inline int parseToken(const std::string& tok) {
  if (tok == "*") return kDontCare;
  if (tok == ".") return 0;
  if (tok.empty() || tok.size() > 3) return -2;
  int v = 0;
  for (char ch : tok) {
    if (ch < '0' || ch > '9') return -2;
    v = v * 10 + (ch - '0');
  }
  return v <= 255 ? v : -2;
}

inline std::string cell(int v) {
  if (v == kDontCare) return "*";
  if (v == 0) return ".";
  return std::to_string(v);
}

inline std::string padLeft(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

}  // namespace stencil_picture_detail

inline ::testing::AssertionResult stencilMatches(const mpr::Framebuffer& fb, int x0, int y0,
                                                 std::string_view picture) {
  namespace d = stencil_picture_detail;
  const auto rows = d::tokenize(picture);
  if (rows.empty()) return ::testing::AssertionFailure() << "the expected stencil picture is empty";
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows[0].size());
  for (int r = 0; r < h; ++r)
    if (static_cast<int>(rows[r].size()) != w)
      return ::testing::AssertionFailure()
             << "malformed stencil picture: row " << r + 1 << " has " << rows[r].size()
             << " tokens, row 1 has " << w;
  if (x0 < 0 || y0 < 0 || x0 + w > fb.width() || y0 + h > fb.height())
    return ::testing::AssertionFailure()
           << "the stencil picture (" << w << "x" << h << " with bottom-left pixel (" << x0 << ","
           << y0 << ")) reaches outside the " << fb.width() << "x" << fb.height() << " window";

  // expected[r][c] and actual[r][c] with r = 0 the top row (window y = y0 + h - 1).
  std::vector<std::vector<int>> expected(h, std::vector<int>(w)), actual(h, std::vector<int>(w));
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const int v = d::parseToken(rows[r][c]);
      if (v == -2)
        return ::testing::AssertionFailure()
               << "malformed stencil picture: token '" << rows[r][c] << "' in row " << r + 1
               << ", column " << c + 1 << " (want a decimal 0..255, '.' or '*')";
      expected[r][c] = v;
      actual[r][c] = fb.stencil(x0 + c, y0 + h - 1 - r);
    }
  }

  struct Miss {
    int x, y, want, got;
  };
  std::vector<Miss> misses;
  std::vector<bool> rowBad(h, false);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (expected[r][c] != d::kDontCare && expected[r][c] != actual[r][c]) {
        misses.push_back({x0 + c, y0 + h - 1 - r, expected[r][c], actual[r][c]});
        rowBad[r] = true;
      }
  if (misses.empty()) return ::testing::AssertionSuccess();

  // Side-by-side pictures, one column width for both.
  std::size_t cw = 1;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      cw = std::max(cw, d::cell(expected[r][c]).size());
      cw = std::max(cw, d::cell(actual[r][c]).size());
    }
  const std::size_t pictureWidth = static_cast<std::size_t>(w) * (cw + 1);
  const std::string ylabel = "y=" + std::to_string(y0 + h - 1);
  const std::size_t lw = ylabel.size();

  std::ostringstream out;
  out << misses.size() << " stencil value(s) differ in the " << w << "x" << h
      << " region with bottom-left pixel (" << x0 << "," << y0 << ")\n";
  out << std::string(lw, ' ') << " " << d::padLeft("expected", pictureWidth) << "   |"
      << d::padLeft("stored", pictureWidth) << "\n";
  for (int r = 0; r < h; ++r) {
    out << d::padLeft("y=" + std::to_string(y0 + h - 1 - r), lw) << " ";
    for (int c = 0; c < w; ++c) out << " " << d::padLeft(d::cell(expected[r][c]), cw);
    out << "   |";
    for (int c = 0; c < w; ++c) out << " " << d::padLeft(d::cell(actual[r][c]), cw);
    if (rowBad[r]) out << "   <<";
    out << "\n";
  }
  out << "mismatching pixels (x,y): expected vs stored\n";
  for (const Miss& m : misses)
    out << "  (" << m.x << "," << m.y << "): expected " << m.want << ", stored " << m.got << "\n";
  return ::testing::AssertionFailure() << out.str();
}

}  // namespace mpr::test
