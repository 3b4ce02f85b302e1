#pragma once
// The files a command writes, checked together before any work and written
// together at the end: every output is validated (a name, not a folder, a
// parent that can be a folder, no two flags naming the same file) before the
// render starts, and every file goes to its own temporary (util/atomic_file)
// before the first is renamed into place, so a failure leaves every earlier
// output as it was and creates no folder.
#include <memory>
#include <string>
#include <vector>

#include "util/atomic_file.hpp"

namespace mpr::cli {

class OutputSet {
 public:
  explicit OutputSet(std::string command) : command_(std::move(command)) {}
  ~OutputSet();  // removes the folders it created unless committed

  // An output file given by `flag` (e.g. "-o", "--trace").
  void addFile(const std::string& flag, const std::string& path);
  // An output folder given by `flag` (e.g. "--dump").
  void addFolder(const std::string& flag, const std::string& dir);
  // "mpr COMMAND: FLAG ...: why" for the first unusable output, or empty.
  std::string problem() const;

  // Writing, after problem() was empty: creates the parent folders and a
  // temporary for `path`, to be filled by the caller (write(), or an image
  // writer handed the temporary) and committed by commit().
  AtomicFile& open(const std::string& path);
  void write(const std::string& path, const std::string& bytes);
  void commit();

 private:
  void createParents(const std::string& path);
  struct Entry {
    std::string flag, path;
    bool folder;
  };
  std::string command_;
  std::vector<Entry> entries_;
  std::vector<std::unique_ptr<AtomicFile>> pending_;
  std::vector<std::string> createdFolders_;
  bool committed_ = false;
};

}  // namespace mpr::cli
