// The util/ pieces issue 15 added against hostile input: reading only
// regular files up to a limit, bounded spelling suggestions, saturating
// counts, and control characters kept off the terminal.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "util/input_file.hpp"
#include "util/printable_text.hpp"
#include "util/saturating.hpp"
#include "util/spelling.hpp"

namespace mpr {
namespace {
namespace fs = std::filesystem;

TEST(InputFile, RefusesFoldersDevicesFifosAndOversizedFiles) {
  char t[] = "/tmp/mpr-input-XXXXXX";
  const fs::path d = mkdtemp(t);
  std::ofstream(d / "small") << "12345";
  EXPECT_EQ(readInputFile((d / "small").string(), 5, "the file"), "12345");
  EXPECT_NE(inputFileProblem((d / "small").string(), 4, "the file").find("more than the 4 bytes MPR reads"),
            std::string::npos);
  EXPECT_NE(inputFileProblem(d.string(), 100, "the file").find("it is a folder"), std::string::npos);
  EXPECT_NE(inputFileProblem("/dev/zero", 100, "the file").find("not a regular file"), std::string::npos);
  ASSERT_EQ(mkfifo((d / "fifo").c_str(), 0600), 0);
  // Opened without blocking, and refused: no writer is waited for.
  EXPECT_NE(inputFileProblem((d / "fifo").string(), 100, "the file").find("not a regular file"), std::string::npos);
  EXPECT_NE(inputFileProblem((d / "none").string(), 100, "the file").find("No such file"), std::string::npos);
  EXPECT_THROW(readInputFile("/dev/zero", 100, "the file"), std::runtime_error);
  fs::remove_all(d);
}

TEST(InputFile, ReadsWhatTheFileHoldsWhateverStatSays) {
  char t[] = "/tmp/mpr-input-XXXXXX";
  const fs::path d = mkdtemp(t);
  // Larger than a read chunk, bytes of every value, not a multiple of 4096.
  std::string big(200003, '\0');
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7919 % 251);
  std::ofstream(d / "big", std::ios::binary) << big;
  EXPECT_EQ(readInputFile((d / "big").string(), big.size(), "the file"), big);
  std::ofstream(d / "empty").close();
  EXPECT_EQ(readInputFile((d / "empty").string(), 10, "the file"), "");
  // A regular file whose size stat gives as 0 (procfs) is read to its end.
  const std::string status = readInputFile("/proc/self/status", 1 << 20, "the file");
  EXPECT_NE(status.find("Name:"), std::string::npos);
  EXPECT_EQ(status.find('\0'), std::string::npos);
  // Past the limit while read (stat said 0): refused, not cut short.
  try {
    readInputFile("/proc/self/status", 10, "the file");
    ADD_FAILURE() << "read past the limit";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "cannot read the file: it grew past the 10 bytes MPR reads");
  }
  fs::remove_all(d);
}

TEST(Spelling, BoundedSuggestionsMatchTheFullDistance) {
  const std::vector<std::string_view> names = {"glBegin", "glEnd", "glVertex3f", "glColor3f", "glClear"};
  EXPECT_EQ(closestMatch("glBgin", names, 3), "glBegin");
  EXPECT_EQ(closestMatch("glVertx3f", names, 3), "glVertex3f");
  EXPECT_EQ(closestMatch("glEnf", names, 3), "glEnd");
  EXPECT_EQ(closestMatch("xxxxxxxx", names, 3), "");
  EXPECT_EQ(closestMatch("GLCLEAR", names, 3, true), "glClear");
  // Every name within the limit is found as the full distance finds it.
  for (std::string_view a : {"glBegin", "glBgin", "lBegin", "glBeginn", "gBegn", "abc", ""})
    for (std::string_view b : names) {
      const std::size_t d = editDistance(a, b);
      EXPECT_EQ(closestMatch(a, {b}, 4) == std::string(b), d < 4) << a << " " << b << " " << d;
    }
}

TEST(Spelling, AHugeUnknownNameCostsLittle) {
  // Issue 15: a 1 MB unknown call took 4.7 s; the band and the length bound make it linear.
  const std::string huge(1 << 20, 'g');
  std::vector<std::string> longNames;
  for (int i = 0; i < 20000; ++i) {
    std::string n = "m";  // appended: GCC 12 warns falsely (-Wrestrict) on "m" + string
    n += std::to_string(i);
    n += std::string(200, 'x');
    longNames.push_back(n);
  }
  std::vector<std::string_view> views(longNames.begin(), longNames.end());
  EXPECT_EQ(closestMatch(huge, views, 3), "");
  const std::string m17 = std::string("m17").append(200, 'x');
  EXPECT_EQ(closestMatch(m17 + "q", views, 3), m17);
}

TEST(Saturating, CountsStopAtTheMaximum) {
  EXPECT_EQ(saturatingAdd(1, 2), 3u);
  EXPECT_EQ(saturatingAdd(kSaturated - 1, 2), kSaturated);
  EXPECT_EQ(saturatingMul(1u << 31, 1u << 31), std::uint64_t{1} << 62);
  EXPECT_EQ(saturatingMul(std::uint64_t{1} << 32, std::uint64_t{1} << 32), kSaturated);
  EXPECT_EQ(countText(12), "12");
  EXPECT_EQ(countText(kSaturated), "more than 18446744073709551614");
}

TEST(PrintableText, EscapesControlCharacters) {
  EXPECT_EQ(printableText("glBog\x1b[31mus"), "glBog\\x1b[31mus");
  EXPECT_EQ(printableText(std::string("a\0b\r\x7f\tc", 7)), "a\\x00b\\x0d\\x7f\tc");
  EXPECT_EQ(printableText("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 passes
}

// A 10 MB unknown name is quoted by its ends: the message keeps its place
// and its reason, and stays under 1 KiB and a bit.
TEST(PrintableText, CutsAHugeMessageInTheMiddle) {
  const std::string exact(kMaxPrintableBytes, 'g');
  EXPECT_EQ(printableText(exact), exact);
  const std::string huge = "f.gls:1:1: '" + std::string(10'000'000, 'g') + "' is not a call";
  const std::string cut = printableText(huge);
  EXPECT_EQ(cut.rfind("f.gls:1:1: 'ggg", 0), 0u);
  EXPECT_EQ(cut.substr(cut.size() - 15), "' is not a call");
  EXPECT_NE(cut.find(" ... (" + std::to_string(huge.size() - 900) + " bytes left out) ... "), std::string::npos);
  EXPECT_LT(cut.size(), kMaxPrintableBytes + 64);
  // A cut never splits a UTF-8 sequence: after "x", byte 600 is the second
  // byte of a two-byte character, so the cut moves back to byte 599.
  std::string accents;
  while (accents.size() < 2000) accents += "\xc3\xa9";
  const std::string t = printableText("x" + accents);
  EXPECT_EQ(t.substr(0, 599 + 5), "x" + accents.substr(0, 598) + " ... ");
}

}  // namespace
}  // namespace mpr
