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

struct AtomicFileFolder : testing::TempFolder {
  AtomicFileFolder() : TempFolder("mpr-atomic") {}
};

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::size_t entries(const fs::path& dir) { return testing::TempFolder::entryCount(dir); }

TEST(AtomicFile, WritesAndLeavesNoTemporary) {
  AtomicFileFolder d;
  writeFileAtomically((d.path / "a.txt").string(), "hello");
  EXPECT_EQ(contents(d.path / "a.txt"), "hello");
  EXPECT_EQ(entries(d.path), 1u);
}

TEST(AtomicFile, NoNameExistsUntilTheFileIsCompleteThenAFreshHiddenOne) {
  AtomicFileFolder d;
  AtomicFile f((d.path / "img.png").string());
  f.write("bytes");
  // While it is written the file has no name another process could swap.
  EXPECT_EQ(entries(d.path), 0u);
  EXPECT_EQ(f.temporaryName(), "");
  f.finish();
  const fs::path tmp = d.path / f.temporaryName();
  EXPECT_EQ(tmp.extension(), ".png");
  EXPECT_EQ(tmp.filename().string().rfind(".img.tmp-", 0), 0u) << tmp;
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(tmp)));
  EXPECT_EQ(contents(tmp), "bytes");
  AtomicFile g((d.path / "img.png").string());
  g.finish();
  EXPECT_NE(g.temporaryName(), f.temporaryName());  // random, not the PID
  f.commit();
  EXPECT_EQ(contents(d.path / "img.png"), "bytes");
}

// Issue 48: a writer that opens its file by name (OpenImageIO) was handed
// the temporary's name, which another process could replace with a link to
// a file of its choosing between the creation and the open. Here the
// "other process" replaces every name in the folder with such a link after
// the file is created: the writer still reaches this object's own file.
TEST(AtomicFile, AWriterThatOpensByNameReachesItsOwnFileWhateverTheFolderHolds) {
  AtomicFileFolder d;
  fs::create_directory(d.path / "out");
  std::ofstream(d.path / "victim") << "victim";
  AtomicFile f((d.path / "out" / "img.tif").string());
  for (const fs::directory_entry& e : fs::directory_iterator(d.path / "out")) {
    fs::remove(e.path());
    fs::create_symlink(d.path / "victim", e.path());
  }
  std::ofstream(f.descriptorPath(), std::ios::binary) << "image";
  f.commit();
  EXPECT_EQ(contents(d.path / "victim"), "victim");
  EXPECT_EQ(contents(d.path / "out" / "img.tif"), "image");
  EXPECT_FALSE(fs::is_symlink(d.path / "out" / "img.tif"));
}

TEST(AtomicFile, ATemporaryNameReplacedBeforeTheRenameIsRefused) {
  AtomicFileFolder d;
  std::ofstream(d.path / "victim") << "victim";
  AtomicFile f((d.path / "out.txt").string());
  f.write("new");
  f.finish();
  const fs::path tmp = d.path / f.temporaryName();
  fs::remove(tmp);
  fs::create_symlink(d.path / "victim", tmp);
  EXPECT_THROW(f.commit(), std::runtime_error);
  EXPECT_FALSE(fs::exists(fs::symlink_status(d.path / "out.txt")));
  EXPECT_EQ(contents(d.path / "victim"), "victim");
}

TEST(AtomicFile, TheFolderIsHeldFromTheStart) {
  // The target's folder renamed away and a link put in its place mid-write:
  // the file lands in the folder that was opened, not through the link.
  AtomicFileFolder d;
  fs::create_directory(d.path / "out");
  fs::create_directory(d.path / "elsewhere");
  AtomicFile f((d.path / "out" / "a.txt").string());
  f.write("a");
  fs::rename(d.path / "out", d.path / "moved");
  fs::create_directory_symlink(d.path / "elsewhere", d.path / "out");
  f.commit();
  EXPECT_EQ(contents(d.path / "moved" / "a.txt"), "a");
  EXPECT_EQ(entries(d.path / "elsewhere"), 0u);
}

TEST(AtomicFile, ALinkAtTheTargetIsReplacedNotFollowed) {
  AtomicFileFolder d;
  std::ofstream(d.path / "victim") << "victim";
  fs::create_symlink(d.path / "victim", d.path / "out.txt");
  writeFileAtomically((d.path / "out.txt").string(), "new");
  EXPECT_EQ(contents(d.path / "victim"), "victim");
  EXPECT_FALSE(fs::is_symlink(d.path / "out.txt"));
  EXPECT_EQ(contents(d.path / "out.txt"), "new");
}

TEST(AtomicFile, UncommittedLeavesTheOldFileAndRemovesTheTemporary) {
  AtomicFileFolder d;
  std::ofstream(d.path / "out.txt") << "old";
  {
    AtomicFile f((d.path / "out.txt").string());
    f.write("half");
  }
  EXPECT_EQ(contents(d.path / "out.txt"), "old");
  EXPECT_EQ(entries(d.path), 1u);
}

TEST(AtomicFile, AGroupIsReplacedWholeOrNotAtAll) {
  AtomicFileFolder d;
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
  AtomicFileFolder d;
  try {
    writeFileAtomically((d.path / "no" / "a").string(), "x");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

TEST(OutputFileProblem, NamesWhatCannotBeWritten) {
  AtomicFileFolder d;
  std::ofstream(d.path / "file") << "x";
  EXPECT_EQ(outputFileProblem((d.path / "new.png").string()), "");
  EXPECT_EQ(outputFileProblem((d.path / "sub" / "new.png").string()), "");
  EXPECT_EQ(outputFileProblem(""), "an empty name is not a file to write");
  EXPECT_NE(outputFileProblem(d.path.string()).find("is a folder"), std::string::npos);
  EXPECT_NE(outputFileProblem((d.path / "file" / "x.png").string()).find("is not a folder"), std::string::npos);
  EXPECT_NE(outputFileProblem("/dev/null").find("not a regular file"), std::string::npos);
}

TEST(OutputReplacesInput, ByTheFilesIdentityNotItsSpelling) {
  AtomicFileFolder d;
  std::ofstream(d.path / "scene.yaml") << "s";
  fs::create_directory(d.path / "sub");
  fs::create_directory_symlink(d.path / "sub", d.path / "via");
  const std::string scene = (d.path / "scene.yaml").string();
  EXPECT_TRUE(outputReplacesInput(scene, scene));
  EXPECT_TRUE(outputReplacesInput((d.path / "sub" / ".." / "scene.yaml").string(), scene));
  // A hard link is the same file under another name.
  fs::create_hard_link(d.path / "scene.yaml", d.path / "sub" / "hard.yaml");
  EXPECT_TRUE(outputReplacesInput((d.path / "via" / "hard.yaml").string(), scene));
  // An input read through a link: the link's own name and the file it reaches.
  fs::create_symlink(d.path / "scene.yaml", d.path / "link.yaml");
  EXPECT_TRUE(outputReplacesInput(scene, (d.path / "link.yaml").string()));
  EXPECT_TRUE(outputReplacesInput((d.path / "link.yaml").string(), (d.path / "link.yaml").string()));
  // An output that is a link to the input is replaced, not followed: the input stays.
  EXPECT_FALSE(outputReplacesInput((d.path / "link.yaml").string(), scene));
  std::ofstream(d.path / "other.yaml") << "o";
  EXPECT_FALSE(outputReplacesInput((d.path / "other.yaml").string(), scene));
  EXPECT_FALSE(outputReplacesInput((d.path / "new.yaml").string(), scene));
}

TEST(SameOutputFile, SeesThroughSpellingsAndLinks) {
  AtomicFileFolder d;
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
