#include "framebuffer/stencil_picture.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace mpr {
namespace {

constexpr int kDontCare = -1;
constexpr int kMalformed = -2;

// Rows of blank-separated tokens; lines holding only blanks are dropped.
std::vector<std::vector<std::string>> tokenize(std::string_view picture) {
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

int parseToken(const std::string& tok) {
  if (tok == "*") return kDontCare;
  if (tok == ".") return 0;
  if (tok.empty() || tok.size() > 3) return kMalformed;
  int v = 0;
  for (char ch : tok) {
    if (ch < '0' || ch > '9') return kMalformed;
    v = v * 10 + (ch - '0');
  }
  return v <= 255 ? v : kMalformed;
}

std::string cell(int v) {
  if (v == kDontCare) return "*";
  if (v == 0) return ".";
  return std::to_string(v);
}

std::string padLeft(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

}  // namespace

std::string stencilPicture(const Framebuffer& fb, const PixelRect& region) {
  const PixelRect r = region.intersect(fb.bounds());
  std::ostringstream out;
  for (int y = r.y1 - 1; y >= r.y0; --y) {
    for (int x = r.x0; x < r.x1; ++x) out << padLeft(cell(fb.stencil(x, y)), 4);
    out << "\n";
  }
  return out.str();
}

std::string stencilPictureMismatch(const Framebuffer& fb, int x0, int y0, std::string_view picture) {
  const auto rows = tokenize(picture);
  if (rows.empty()) return "the expected stencil picture is empty";
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows[0].size());
  for (int r = 0; r < h; ++r)
    if (static_cast<int>(rows[r].size()) != w)
      return "malformed stencil picture: row " + std::to_string(r + 1) + " has " + std::to_string(rows[r].size()) +
             " tokens, row 1 has " + std::to_string(w);
  if (x0 < 0 || y0 < 0 || x0 + w > fb.width() || y0 + h > fb.height())
    return "the stencil picture (" + std::to_string(w) + "x" + std::to_string(h) + " with bottom-left pixel (" +
           std::to_string(x0) + "," + std::to_string(y0) + ")) reaches outside the " + std::to_string(fb.width()) +
           "x" + std::to_string(fb.height()) + " window";

  // expected[r][c] and stored[r][c], r = 0 the top row (window y = y0 + h - 1).
  std::vector<std::vector<int>> expected(h, std::vector<int>(w)), stored(h, std::vector<int>(w));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int v = parseToken(rows[r][c]);
      if (v == kMalformed)
        return "malformed stencil picture: token '" + rows[r][c] + "' in row " + std::to_string(r + 1) +
               ", column " + std::to_string(c + 1) + " (want a decimal 0..255, '.' or '*')";
      expected[r][c] = v;
      stored[r][c] = fb.stencil(x0 + c, y0 + h - 1 - r);
    }

  std::ostringstream misses;
  int missCount = 0;
  std::vector<bool> rowBad(h, false);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (expected[r][c] != kDontCare && expected[r][c] != stored[r][c]) {
        ++missCount;
        rowBad[r] = true;
        misses << "  (" << x0 + c << "," << y0 + h - 1 - r << "): expected " << expected[r][c] << ", stored "
               << stored[r][c] << "\n";
      }
  if (missCount == 0) return {};

  // The two pictures side by side, one column width for both, each row with
  // its window y, differing rows marked.
  std::size_t cw = 1;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) cw = std::max({cw, cell(expected[r][c]).size(), cell(stored[r][c]).size()});
  const std::size_t pictureWidth = static_cast<std::size_t>(w) * (cw + 1);
  const std::size_t lw = ("y=" + std::to_string(y0 + h - 1)).size();
  std::ostringstream out;
  out << missCount << " stencil value(s) differ in the " << w << "x" << h << " region with bottom-left pixel (" << x0
      << "," << y0 << ")\n";
  out << std::string(lw, ' ') << " " << padLeft("expected", pictureWidth) << "   |" << padLeft("stored", pictureWidth)
      << "\n";
  for (int r = 0; r < h; ++r) {
    out << padLeft("y=" + std::to_string(y0 + h - 1 - r), lw) << " ";
    for (int c = 0; c < w; ++c) out << " " << padLeft(cell(expected[r][c]), cw);
    out << "   |";
    for (int c = 0; c < w; ++c) out << " " << padLeft(cell(stored[r][c]), cw);
    if (rowBad[r]) out << "   <<";
    out << "\n";
  }
  out << "mismatching pixels (x,y): expected vs stored\n" << misses.str();
  return out.str();
}

}  // namespace mpr
