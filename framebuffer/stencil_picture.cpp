#include "framebuffer/stencil_picture.hpp"

#include <cstdlib>
#include <sstream>
#include <vector>

namespace mpr {
namespace {

std::vector<std::vector<std::string>> parseRows(std::string_view picture) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in{std::string(picture)};
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<std::string> row;
    for (std::string tok; ls >> tok;) row.push_back(tok);
    if (!row.empty()) rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

std::string stencilPicture(const Framebuffer& fb, const PixelRect& region) {
  const PixelRect r = region.intersect(fb.bounds());
  std::ostringstream out;
  for (int y = r.y1 - 1; y >= r.y0; --y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const unsigned v = fb.stencil(x, y);
      std::string tok = v == 0 ? "." : std::to_string(v);
      out << std::string(4 - tok.size(), ' ') << tok;
    }
    out << "\n";
  }
  return out.str();
}

std::string stencilPictureMismatch(const Framebuffer& fb, int x0, int y0, std::string_view picture) {
  const auto rows = parseRows(picture);
  if (rows.empty()) return "the expected picture is empty";
  const int h = static_cast<int>(rows.size()), w = static_cast<int>(rows[0].size());
  for (const auto& row : rows)
    if (static_cast<int>(row.size()) != w) return "the expected picture has rows of different lengths";
  if (x0 < 0 || y0 < 0 || x0 + w > fb.width() || y0 + h > fb.height())
    return "the expected picture (" + std::to_string(w) + "x" + std::to_string(h) + " at " + std::to_string(x0) +
           "," + std::to_string(y0) + ") reaches outside the window";
  std::ostringstream diffs;
  int mismatches = 0;
  for (int r = 0; r < h; ++r) {
    const int y = y0 + h - 1 - r;
    for (int c = 0; c < w; ++c) {
      const int x = x0 + c;
      const std::string& tok = rows[r][c];
      if (tok == "*") continue;
      long expected = 0;
      if (tok != ".") {
        char* end = nullptr;
        expected = std::strtol(tok.c_str(), &end, 10);
        if (*end != '\0' || expected < 0 || expected > 255)
          return "bad token '" + tok + "' in the expected picture (row " + std::to_string(r + 1) + ")";
      }
      const unsigned actual = fb.stencil(x, y);
      if (actual != static_cast<unsigned>(expected)) {
        if (++mismatches <= 32)
          diffs << "  pixel (" << x << "," << y << "): expected " << expected << ", stored " << actual << "\n";
      }
    }
  }
  if (mismatches == 0) return {};
  std::ostringstream out;
  out << mismatches << " stencil value(s) differ in the " << w << "x" << h << " region at (" << x0 << "," << y0
      << ")\nexpected:\n"
      << picture << "\nstored:\n"
      << stencilPicture(fb, {x0, y0, x0 + w, y0 + h}) << diffs.str();
  return out.str();
}

}  // namespace mpr
