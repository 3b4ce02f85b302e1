// util/atomic_file: a fresh temporary beside the target, never through a
// link, renamed into place; a failure leaves the old file as it was.
#include "util/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "testing/temp_folder.hpp"

namespace mpr {
namespace {
namespace fs = std::filesystem;

struct TempDir : testing::TempFolder {
  TempDir() : TempFolder("mpr-atomic") {}
};

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, WritesAndLeavesNoTemporary) {
  TempDir d;
  writeFileAtomically((d.path / "a.txt").string(), "hello");
  EXPECT_EQ(contents(d.path / "a.txt"), "hello");
  EXPECT_EQ(entries(d.path), 1u);
}

TEST(AtomicFile, TemporaryIsFreshHiddenAndKeepsTheExtension) {
  TempDir d;
  AtomicFile f((d.path / "img.png").string());
  const fs::path tmp = f.temporaryPath();
  EXPECT_EQ(tmp.parent_path(), d.path);
  EXPECT_EQ(tmp.extension(), ".png");
  EXPECT_EQ(tmp.filename().string().rfind(".img.tmp-", 0), 0u) << tmp;
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(tmp)));
  AtomicFile g((d.path / "img.png").string());
  EXPECT_NE(g.temporaryPath(), f.temporaryPath());  // random, not the PID
}

TEST(AtomicFile, ALinkAtTheTargetIsReplacedNotFollowed) {
  TempDir d;
  std::ofstream(d.path / "victim") << "victim";
  fs::create_symlink(d.path / "victim", d.path / "out.txt");
  writeFileAtomically((d.path / "out.txt").string(), "new");
  EXPECT_EQ(contents(d.path / "victim"), "victim");
  EXPECT_FALSE(fs::is_symlink(d.path / "out.txt"));
  EXPECT_EQ(contents(d.path / "out.txt"), "new");
}

TEST(AtomicFile, UncommittedLeavesTheOldFileAndRemovesTheTemporary) {
  TempDir d;
  std::ofstream(d.path / "out.txt") << "old";
  {
    AtomicFile f((d.path / "out.txt").string());
    f.write("half");
  }
  EXPECT_EQ(contents(d.path / "out.txt"), "old");
  EXPECT_EQ(entries(d.path), 1u);
}

TEST(AtomicFile, AGroupIsReplacedWholeOrNotAtAll) {
  TempDir d;
  std::ofstream(d.path / "a") << "old a";
  // The second name is too long for the file system: the first is not replaced.
  const std::string tooLong = (d.path / std::string(300, 'x')).string();
  EXPECT_THROW(writeFilesAtomically({{(d.path / "a").string(), "new a"}, {tooLong, "b"}}), std::runtime_error);
  EXPECT_EQ(contents(d.path / "a"), "old a");
  EXPECT_EQ(entries(d.path), 1u);
  writeFilesAtomically({{(d.path / "a").string(), "new a"}, {(d.path / "b").string(), "b"}});
  EXPECT_EQ(contents(d.path / "a"), "new a");
  EXPECT_EQ(contents(d.path / "b"), "b");
}

TEST(AtomicFile, AMissingFolderIsAnError) {
  TempDir d;
  try {
    writeFileAtomically((d.path / "no" / "a").string(), "x");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

TEST(OutputFileProblem, NamesWhatCannotBeWritten) {
  TempDir d;
  std::ofstream(d.path / "file") << "x";
  EXPECT_EQ(outputFileProblem((d.path / "new.png").string()), "");
  EXPECT_EQ(outputFileProblem((d.path / "sub" / "new.png").string()), "");
  EXPECT_EQ(outputFileProblem(""), "an empty name is not a file to write");
  EXPECT_NE(outputFileProblem(d.path.string()).find("is a folder"), std::string::npos);
  EXPECT_NE(outputFileProblem((d.path / "file" / "x.png").string()).find("is not a folder"), std::string::npos);
  EXPECT_NE(outputFileProblem("/dev/null").find("not a regular file"), std::string::npos);
}

TEST(SameOutputFile, SeesThroughSpellingsAndLinks) {
  TempDir d;
  const std::string a = (d.path / "a.png").string();
  EXPECT_TRUE(sameOutputFile(a, (d.path / "." / "a.png").string()));
  EXPECT_FALSE(sameOutputFile(a, (d.path / "b.png").string()));
  fs::create_directory(d.path / "real");
  fs::create_directory_symlink(d.path / "real", d.path / "link");
  EXPECT_TRUE(sameOutputFile((d.path / "real" / "x").string(), (d.path / "link" / "x").string()));
  // Two links to one file are two outputs: each name's link is replaced, not followed.
  std::ofstream(d.path / "victim") << "v";
  fs::create_symlink(d.path / "victim", d.path / "t.gls");
  fs::create_symlink(d.path / "victim", d.path / "s.json");
  EXPECT_FALSE(sameOutputFile((d.path / "t.gls").string(), (d.path / "s.json").string()));
  EXPECT_TRUE(sameOutputFile((d.path / "t.gls").string(), (d.path / "link" / ".." / "t.gls").string()));
}

}  // namespace
}  // namespace mpr
