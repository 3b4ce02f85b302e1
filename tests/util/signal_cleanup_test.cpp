// util/signal_cleanup: what a write has named but not yet renamed into place
// is removed when SIGINT or SIGTERM ends the process, which still ends by
// that signal (issue 48: hidden temporaries left beside the outputs).
#include "util/signal_cleanup.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "testing/temp_folder.hpp"
#include "util/atomic_file.hpp"

namespace mpr {
namespace {
namespace fs = std::filesystem;

struct SignalFolder : testing::TempFolder {
  SignalFolder() : TempFolder("mpr-signal") {}
};

// Runs `body` in a child process with the handler installed; returns the
// signal that ended the child (0 when it exited).
template <typename Body>
int endedBySignal(Body body) {
  const pid_t pid = fork();
  if (pid == 0) {
    installSignalCleanup();
    body();
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

TEST(SignalCleanup, AnInterruptedWriteLeavesNoTemporaryAndTheOldFile) {
  for (const int sig : {SIGINT, SIGTERM}) {
    SignalFolder d;
    std::ofstream(d.path / "out.png") << "old";
    const int ended = endedBySignal([&] {
      AtomicFile f((d.path / "out.png").string());
      f.write("new");
      f.finish();  // named now: the window an interrupt could leave it in
      std::raise(sig);
    });
    EXPECT_EQ(ended, sig);
    EXPECT_EQ(testing::TempFolder::entryCount(d.path), 1u) << "signal " << sig;
    std::ifstream in(d.path / "out.png");
    std::string text;
    in >> text;
    EXPECT_EQ(text, "old");
  }
}

TEST(SignalCleanup, AHalfMadeFolderIsRemovedWithItsFiles) {
  SignalFolder d;
  const int ended = endedBySignal([&] {
    const int parent = ::open(d.path.c_str(), O_RDONLY | O_DIRECTORY);
    fs::create_directory(d.path / ".page.new-1");
    SignalCleanup folder(parent, ".page.new-1", SignalCleanup::Kind::Folder);
    for (int i = 0; i < 300; ++i) std::ofstream(d.path / ".page.new-1" / std::to_string(i)) << i;
    fs::create_directory(d.path / ".page.new-1" / "empty");
    std::raise(SIGTERM);
  });
  EXPECT_EQ(ended, SIGTERM);
  EXPECT_EQ(testing::TempFolder::entryCount(d.path), 0u);
}

TEST(SignalCleanup, ADeregisteredNameIsLeftAlone) {
  SignalFolder d;
  const int ended = endedBySignal([&] {
    const int parent = ::open(d.path.c_str(), O_RDONLY | O_DIRECTORY);
    std::ofstream(d.path / "kept") << "k";
    SignalCleanup kept(parent, "kept", SignalCleanup::Kind::File);
    kept.release();  // committed: it is an output now
    std::raise(SIGINT);
  });
  EXPECT_EQ(ended, SIGINT);
  EXPECT_TRUE(fs::exists(d.path / "kept"));
}

}  // namespace
}  // namespace mpr
