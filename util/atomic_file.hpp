#pragma once
// Writing files so that a reader never sees half a file, a failed write
// leaves the old file as it was, and nothing outside the output is touched,
// even when another process can write in the output's folder.
//
// The target's folder is opened once and held: every later step is relative
// to that descriptor (openat, linkat, renameat), so a folder swapped for a
// link mid-write moves nothing. The bytes go to a file with no name at all
// (O_TMPFILE) through the descriptor that created it; writers that open by
// name (OpenImageIO) are handed /proc/self/fd/N, which reaches that same
// file whatever a name in the folder has become. Only when the file is
// complete and fsync'd is it linked under a random hidden name, and then
// renamed over the target (a link at the target itself is replaced, not
// followed). Where a file system has no O_TMPFILE the temporary is created
// under its random name with O_CREAT | O_EXCL | O_NOFOLLOW instead. A group
// of files is committed together: every temporary is finished before the
// first rename, so a full disk or a bad path leaves none of them replaced.
// A named temporary is removed if SIGINT or SIGTERM ends the process
// (util/signal_cleanup).
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "util/signal_cleanup.hpp"

namespace mpr {

class AtomicFile {
 public:
  // Opens `target`'s folder and creates the temporary. Throws
  // std::runtime_error naming `target`.
  explicit AtomicFile(std::string target);
  // The same for the file `name` in the folder open as `folderFd` (held by
  // the caller for the object's life); `shown` is the path messages name.
  AtomicFile(int folderFd, const std::string& name, std::string shown);
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  AtomicFile(const AtomicFile&) = delete;
  ~AtomicFile();  // removes the temporary unless committed

  const std::string& target() const { return shown_; }
  // A path that opens this object's own file, for a writer that opens by
  // name: /proc/self/fd/N (the temporary's name where /proc is missing).
  std::string descriptorPath() const;
  // The temporary's name in its folder: empty while it has none (O_TMPFILE,
  // before finish()).
  const std::string& temporaryName() const { return tmpName_; }

  // Appends bytes; throws on a short write (a full disk, `ulimit -f`).
  void write(std::string_view bytes);
  // Flushes the file to disk and gives it its temporary name; throws on
  // failure.
  void finish();
  // Renames the finished temporary over the target; throws on failure, or
  // when the temporary's name no longer holds this object's file.
  void commit();

 private:
  void create();
  std::string shown_, name_, tmpName_;
  int folderFd_ = -1;
  bool ownsFolder_ = false;
  int fd_ = -1;
  bool unnamed_ = false;  // O_TMPFILE: no name until finish()
  bool finished_ = false, committed_ = false;
  SignalCleanup cleanup_;
};

// Writes one file atomically.
void writeFileAtomically(const std::string& path, std::string_view bytes);

// Writes every (path, bytes) pair to its temporary first, then renames them
// all into place: on any failure before the renames none is replaced.
void writeFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files);

// "'PATH' why": the form of every output-path message.
std::string quotedPath(const std::string& path, std::string_view why);

// Why folders cannot be created down to `start` (an absolute folder path):
// the nearest of `start` and its ancestors that exists is not a folder
// (empty when it is one, or when none exists).
std::string existingAncestorProblem(const std::filesystem::path& start);

// Why `path` cannot be written as an output file, or empty when it can: an
// empty name, an existing folder, a parent that exists and is not a folder.
std::string outputFileProblem(const std::string& path);

// True when two output paths name the same file: the same text after
// normalising, or the same name in one folder reached both ways (links to
// folders resolved; a link at the name itself is not, it is replaced).
bool sameOutputFile(const std::string& a, const std::string& b);

// True when writing the output `output` would replace the existing file
// `input`: the output's name (itself, not followed: rename replaces it) is
// the input's name or the file it reaches (by device and inode, so hard
// links and every spelling count). False when either does not exist.
bool outputReplacesInput(const std::string& output, const std::string& input);

}  // namespace mpr
