#pragma once
// Writing files so that a reader never sees half a file, a failed write
// leaves the old file as it was, and nothing outside the output is touched.
//
// A temporary is created in the target's own folder with a random name and
// O_CREAT | O_EXCL | O_NOFOLLOW (never an existing file, never through a
// symbolic link another user planted at a predictable name), written,
// fsync'd, and renamed over the target (rename replaces a link at the target
// itself, it does not follow it). A group of files is committed together:
// every temporary is written before the first rename, so a full disk or a
// bad path leaves none of them replaced.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mpr {

class AtomicFile {
 public:
  // Creates the temporary beside `target` (keeping its extension last, so an
  // image library picks the format from the name). Throws std::runtime_error
  // naming `target`.
  explicit AtomicFile(std::string target);
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  AtomicFile(const AtomicFile&) = delete;
  ~AtomicFile();  // removes the temporary unless committed

  const std::string& target() const { return target_; }
  // The temporary this object created: hand it to a writer that opens by
  // name (OpenImageIO); it is a regular file only this process created.
  const std::string& temporaryPath() const { return tmp_; }

  // Appends bytes; throws on a short write (a full disk, `ulimit -f`).
  void write(std::string_view bytes);
  // Flushes the temporary to disk and closes it; throws on failure.
  void finish();
  // Renames the finished temporary over the target; throws on failure.
  void commit();

 private:
  std::string target_, tmp_;
  int fd_ = -1;
  bool committed_ = false;
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

}  // namespace mpr
