// The documentation's example under "Per-pixel tests in C++"
// (docs/reference/cpp-api.md), compiled so that it
// cannot go wrong again: keep the body of the test below and the page's
// code block the same, line for line.
//
// A 16x16 window under identity matrices: NDC -0.5 .. 0.5 is window 4 .. 12
// both ways, so glRectf covers the pixels 4 .. 11 (centres 4.5 .. 11.5). The
// picture's bottom-left pixel is (3,3): its rows top-down are y = 5, 4, 3;
// its columns x = 3, 4, 5; x = 3 and y = 3 lie outside the square.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "framebuffer/stencil_picture.hpp"
#include "pipeline/gl/gl_context.hpp"

namespace mpr {
namespace {

TEST(DocsExample, PerPixelTestsInCpp) {
  // --- the documentation's code block ---
  mpr::GLContext gl(16, 16, mpr::indigoProfile());
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 129, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(-0.5f, -0.5f, 0.5f, 0.5f);      // window 4 .. 12 both ways: pixels 4 .. 11
  EXPECT_EQ(gl.stencilAt(8, 8), 129u);
  EXPECT_EQ(gl.stencilAt(3, 3), 0u);       // outside the square
  EXPECT_EQ(mpr::stencilPictureMismatch(gl.framebuffer(), 3, 3, R"(
      .  129  129
      .  129  129
      .    .    *)"), "");
  // --- end of the documentation's code block ---
}

// The same picture one pixel off (the example as it first stood, at (2,2)
// with 129 at (3,3)) does not hold: the comparison is not vacuous.
TEST(DocsExample, AWrongPictureIsReported) {
  mpr::GLContext gl(16, 16, mpr::indigoProfile());
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 129, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  gl.rectf(-0.5f, -0.5f, 0.5f, 0.5f);
  EXPECT_NE(mpr::stencilPictureMismatch(gl.framebuffer(), 2, 2, R"(
    .   .   1
    . 129   1
    *   .   .)"), "");
}

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The code block of the first test, unindented, is the documentation's block
// under "Per-pixel tests in C++", byte for byte.
TEST(DocsExample, ThePageShowsThisCode) {
  const std::string self = fileText(std::string(MPR_SOURCE_DIR) + "/tests/pipeline/docs_example_test.cpp");
  const std::string begin = "  // --- the documentation's code block ---\n", end = "  // --- end of the documentation's code block ---";
  const std::size_t from = self.find(begin), to = self.find(end);
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  std::string block;
  std::istringstream lines(self.substr(from + begin.size(), to - from - begin.size()));
  for (std::string line; std::getline(lines, line);) block += (line.rfind("  ", 0) == 0 ? line.substr(2) : line) + "\n";
  const std::string page = fileText(std::string(MPR_SOURCE_DIR) + "/docs/reference/cpp-api.md");
  const std::size_t section = page.find("## Per-pixel tests in C++");
  ASSERT_NE(section, std::string::npos);
  EXPECT_NE(page.find("```cpp\n" + block + "```\n", section), std::string::npos)
      << "docs/reference/cpp-api.md's example differs from this test's:\n" << block;
}

}  // namespace
}  // namespace mpr
