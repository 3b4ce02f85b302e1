#include "util/signal_cleanup.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace mpr {
namespace {

// A fixed table, so that the handler reads no heap and takes no lock.
// state: 0 free, 1 being filled or emptied, 2 registered.
struct Slot {
  std::atomic<int> state{0};
  int folderFd = -1;
  SignalCleanup::Kind kind = SignalCleanup::Kind::File;
  char name[NAME_MAX + 1] = {};
};
constexpr int kSlots = 256;
Slot slots[kSlots];

void onSignal(int sig) {
  // Newest first: a page folder's files before the folder.
  for (int i = kSlots - 1; i >= 0; --i) {
    Slot& s = slots[i];
    if (s.state.load(std::memory_order_acquire) != 2) continue;
    if (s.kind == SignalCleanup::Kind::File) ::unlinkat(s.folderFd, s.name, 0);
    else removeFlatFolder(s.folderFd, s.name);
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

SignalCleanup::SignalCleanup(int folderFd, std::string_view name, Kind kind) {
  if (name.empty() || name.size() > NAME_MAX) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!slots[i].state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) continue;
    slots[i].folderFd = folderFd;
    slots[i].kind = kind;
    std::memcpy(slots[i].name, name.data(), name.size());
    slots[i].name[name.size()] = '\0';
    slots[i].state.store(2, std::memory_order_release);
    slot_ = i;
    return;
  }
}

SignalCleanup::SignalCleanup(SignalCleanup&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }

SignalCleanup& SignalCleanup::operator=(SignalCleanup&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

SignalCleanup::~SignalCleanup() { release(); }

void SignalCleanup::release() {
  if (slot_ < 0) return;
  slots[slot_].state.store(0, std::memory_order_release);
  slot_ = -1;
}

void removeFlatFolder(int parentFd, const char* name) {
  const int fd = ::openat(parentFd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd >= 0) {
    alignas(8) char buf[4096];
    // Read from the start again after each pass that removed something
    // (removing entries while reading on is not defined to see every one);
    // a pass that removes nothing ends it ('.' and '..' are always there).
    for (bool removed = true; removed;) {
      removed = false;
      ::lseek(fd, 0, SEEK_SET);
      for (long n; (n = ::syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;)
        for (long off = 0; off < n;) {
          const auto* d = reinterpret_cast<const struct dirent64*>(buf + off);
          off += d->d_reclen;
          if (std::strcmp(d->d_name, ".") == 0 || std::strcmp(d->d_name, "..") == 0) continue;
          // An empty folder in it goes too.
          if (::unlinkat(fd, d->d_name, 0) == 0 || ::unlinkat(fd, d->d_name, AT_REMOVEDIR) == 0) removed = true;
        }
    }
    ::close(fd);
  }
  ::unlinkat(parentFd, name, AT_REMOVEDIR);
}

void installSignalCleanup() {
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  // The other ending signals wait while one handler runs (no second pass
  // over a half-removed folder).
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&sa.sa_mask, s);
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    struct sigaction old {};
    // A signal the parent set to be ignored (nohup, a shell's background
    // job) stays ignored.
    if (::sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(s, &sa, nullptr);
  }
}

}  // namespace mpr
