#include "testing/gtest_helpers.hpp"

#include <functional>
#include <sstream>

namespace mpr::testing {
namespace {

// The mismatched runs of one buffer: consecutive differing pixels of a row.
::testing::AssertionResult compare(const char* buffer, const Framebuffer& e, const Framebuffer& a, std::size_t maxRuns,
                                   const std::function<std::string(const Framebuffer&, int, int)>& value) {
  if (e.width() != a.width() || e.height() != a.height())
    return ::testing::AssertionFailure() << buffer << " buffers differ in size: expected " << e.width() << "x"
                                         << e.height() << ", found " << a.width() << "x" << a.height();
  std::ostringstream runs;
  std::size_t count = 0, pixels = 0;
  for (int y = 0; y < e.height(); ++y)
    for (int x = 0; x < e.width();) {
      if (value(e, x, y) == value(a, x, y)) {
        ++x;
        continue;
      }
      int end = x;
      std::string want, found;
      while (end < e.width() && value(e, end, y) != value(a, end, y)) {
        if (end > x) want += ' ', found += ' ';
        want += value(e, end, y);
        found += value(a, end, y);
        ++end;
      }
      pixels += static_cast<std::size_t>(end - x);
      if (count++ < maxRuns)
        runs << "  y=" << y << ", x " << x << ".." << end - 1 << ": expected " << want << ", found " << found << "\n";
      x = end;
    }
  if (count == 0) return ::testing::AssertionSuccess();
  auto f = ::testing::AssertionFailure();
  f << pixels << " " << buffer << " pixel(s) differ in " << count << " run(s)\n" << runs.str();
  if (count > maxRuns) f << "  ... and " << count - maxRuns << " more run(s)\n";
  return f;
}

}  // namespace

::testing::AssertionResult stencilBuffersEqual(const Framebuffer& e, const Framebuffer& a, std::size_t maxRuns) {
  return compare("stencil", e, a, maxRuns,
                 [](const Framebuffer& fb, int x, int y) { return std::to_string(fb.stencil(x, y)); });
}

::testing::AssertionResult depthBuffersEqual(const Framebuffer& e, const Framebuffer& a, std::size_t maxRuns) {
  return compare("depth", e, a, maxRuns,
                 [](const Framebuffer& fb, int x, int y) { return std::to_string(fb.depth(x, y)); });
}

::testing::AssertionResult colorBuffersEqual(const Framebuffer& e, const Framebuffer& a, std::size_t maxRuns) {
  return compare("colour", e, a, maxRuns, [](const Framebuffer& fb, int x, int y) {
    const Rgba8& c = fb.color(x, y);
    std::string text = "(";  // appended, not "(" + ...: GCC 12's -Wrestrict false positive
    for (int i = 0; i < 4; ++i) {
      if (i > 0) text += ',';
      text += std::to_string(c[static_cast<std::size_t>(i)]);
    }
    return text + ")";
  });
}

}  // namespace mpr::testing
