#pragma once
// Names a write has put in a folder but not yet renamed into place (a
// linked temporary, a page folder being filled), removed when SIGINT,
// SIGTERM, SIGHUP or SIGQUIT ends the process: an interrupted command leaves
// its earlier outputs as they were and no hidden temporary beside them.
//
// Registering is always safe; the handler is installed only by the `mpr`
// executable (installSignalCleanup), a process-wide choice a host program
// that links the libraries makes for itself. The handler uses only
// async-signal-safe calls (unlinkat, openat, getdents64, close), then ends
// the process by the signal's default action, so the exit status still says
// which signal it was.
#include <string_view>

namespace mpr {

class SignalCleanup {
 public:
  enum class Kind { File, Folder };  // a Folder is emptied (one level deep), then removed
  SignalCleanup() = default;
  // Registers `name` in the folder open as `folderFd` (which must stay open
  // while registered). A name longer than NAME_MAX, or a full table (256
  // names), is not registered: the write still works, only an interrupt
  // could leave that name behind.
  SignalCleanup(int folderFd, std::string_view name, Kind kind);
  SignalCleanup(SignalCleanup&& other) noexcept;
  SignalCleanup& operator=(SignalCleanup&& other) noexcept;
  SignalCleanup(const SignalCleanup&) = delete;
  SignalCleanup& operator=(const SignalCleanup&) = delete;
  ~SignalCleanup();  // deregisters (does not remove anything)
  void release();    // deregisters now

 private:
  int slot_ = -1;
};

// Removes the folder `name` in the folder open as `parentFd` and every entry
// in it (one level deep: a page folder holds files only). Async-signal-safe;
// the handler's own way to remove a page folder, and the page writer's.
void removeFlatFolder(int parentFd, const char* name);

// Installs the handler for SIGINT, SIGTERM, SIGHUP and SIGQUIT (those whose
// default action ends the process). For the mpr executable's main().
void installSignalCleanup();

}  // namespace mpr
