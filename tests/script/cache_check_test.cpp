// The cache-check build (MPR_CHECK_CACHES, the sanitizer build): a cache hit
// whose stored value is not what the function gives now aborts. Outside that
// build the hit is trusted, and these tests are skipped.
#include <gtest/gtest.h>

#include "script/gl_script.hpp"
#include "util/check.hpp"
#include "util/recent_results.hpp"

namespace mpr {
namespace {

TEST(CacheCheck, AHitThatDiffersFromTheFunctionAborts) {
  if (!kCheckCaches) GTEST_SKIP() << "built without MPR_CHECK_CACHES";
  RecentResults<std::uint32_t, std::uint32_t, 16> recent;
  std::uint32_t calls = 0;
  const auto impure = [&](std::uint32_t key) { return key + calls++; };  // not a function of its key
  EXPECT_EQ(recent.get(7, impure), 7u);
  EXPECT_DEATH(recent.get(7, impure), "memcmp");
}

TEST(CacheCheck, AHitThatAgreesPasses) {
  if (!kCheckCaches) GTEST_SKIP() << "built without MPR_CHECK_CACHES";
  RecentResults<std::uint32_t, std::uint32_t, 16> recent;
  int computed = 0;
  const auto twice = [&](std::uint32_t key) { ++computed; return 2 * key; };
  EXPECT_EQ(recent.get(7, twice), 14u);
  EXPECT_EQ(recent.get(7, twice), 14u);
  EXPECT_EQ(computed, 2);  // the hit computed it again, to compare
}

// A script whose lines and numbers repeat: every RecentLines and
// RecentDecimals hit is parsed again and compared in this build.
TEST(CacheCheck, RepeatedLinesParseAsTheirFirstParse) {
  std::string text = "@framebuffer 4 4\nglBegin GL_TRIANGLES\n";
  for (int i = 0; i < 300; ++i) text += "glVertex3f 0.25 -1.5 " + std::to_string(i % 7) + ".5\n";
  text += "glEnd\n";
  const Script s = parseScript(text, "repeat.gls");
  ASSERT_EQ(s.callCount(), 302u);
  EXPECT_EQ(s.commands[1].args[0].number, 0.25);
  EXPECT_EQ(s.commands[300].args[2].number, 5.5);  // i = 299: 299 % 7 = 5
}

}  // namespace
}  // namespace mpr
