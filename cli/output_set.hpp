#pragma once
// The files a command writes, checked together before any work and written
// together at the end: every output is validated (a name, not a folder, a
// parent that can be a folder, no two flags naming the same file) before the
// render starts, and every file goes to its own temporary (util/atomic_file)
// before the first is renamed into place, so a failure leaves every earlier
// output as it was and creates no folder.
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "util/atomic_file.hpp"
#include "util/signal_cleanup.hpp"

namespace mpr::cli {

class OutputSet {
 public:
  explicit OutputSet(std::string command) : command_(std::move(command)) {}
  ~OutputSet();  // removes the folders it created unless committed

  // An output file given by `flag` (e.g. "-o", "--trace").
  void addFile(const std::string& flag, const std::string& path);
  // An output folder given by `flag` (e.g. "--dump") into which the command
  // writes the files `names`, and any file whose name ends in `anySuffix`
  // (when not empty: names known only as the run goes, snapshots).
  void addFolder(const std::string& flag, const std::string& dir, std::vector<std::string> names = {},
                 std::string anySuffix = {});
  // A file the command reads (`what`: "the scene", "the mesh", "the
  // script"): no output may replace it.
  void addInput(const std::string& what, const std::string& path);
  // The scene file and every mesh file it read.
  void addSceneInputs(const Scene& scene);
  // "mpr COMMAND: FLAG ...: why" for the first unusable output, or empty:
  // a name that cannot be written, two outputs naming one file, or an
  // output that would replace an input (by the file's identity: every
  // spelling, link and hard link of it).
  std::string problem() const;

  // Writing, after problem() was empty: creates the parent folders and a
  // temporary for `path`, to be filled by the caller (write(), or an image
  // writer handed the file) and committed by commit(). Every file is made
  // from its folder's descriptor, opened once: folders this set creates are
  // opened without following links, so another process cannot redirect a
  // file by swapping a folder for a link.
  AtomicFile& open(const std::string& path);
  void write(const std::string& path, const std::string& bytes);
  // Creates `dir` (and what is missing above it) now, even if no file goes
  // into it; returns its descriptor, held by this set until it is destroyed.
  int createFolder(const std::string& dir);
  void commit();

 private:
  int folderFd(const std::string& dir);
  std::runtime_error folderError(const std::filesystem::path& dir, int err) const;
  struct Entry {
    std::string flag, path;
    bool folder;
    std::vector<std::string> names;  // a folder's files
    std::string anySuffix;
  };
  struct Input {
    std::string what, path;
  };
  std::string inputProblem(const Entry& e) const;
  std::string command_;
  std::vector<Entry> entries_;
  std::vector<Input> inputs_;
  std::vector<std::unique_ptr<AtomicFile>> pending_;
  struct CreatedFolder {
    int parentFd;  // held in folderFds_
    std::string name;
    SignalCleanup cleanup;
  };
  std::vector<CreatedFolder> createdFolders_;
  std::map<std::string, int> folderFds_;  // absolute folder path -> its open descriptor
  bool committed_ = false;
};

// "color.npy", "depth.npy", ...: the files of a --dump folder's final buffers.
std::vector<std::string> npyDumpFileNames();

}  // namespace mpr::cli
