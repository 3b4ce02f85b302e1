#include "cli/output_set.hpp"

#include <filesystem>
#include <system_error>

namespace mpr::cli {
namespace fs = std::filesystem;

namespace {

std::string folderProblem(const std::string& dir) {
  if (dir.empty()) return "an empty name is not a folder to write";
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st)) return quotedPath(dir, "exists and is not a folder");
  return existingAncestorProblem(fs::absolute(dir, ec).lexically_normal());
}

}  // namespace

OutputSet::~OutputSet() {
  pending_.clear();  // removes the temporaries first
  if (committed_) return;
  std::error_code ec;
  for (auto it = createdFolders_.rbegin(); it != createdFolders_.rend(); ++it) fs::remove(*it, ec);  // only if empty
}

void OutputSet::addFile(const std::string& flag, const std::string& path) { entries_.push_back({flag, path, false}); }
void OutputSet::addFolder(const std::string& flag, const std::string& dir) { entries_.push_back({flag, dir, true}); }

std::string OutputSet::problem() const {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    const std::string why = e.folder ? folderProblem(e.path) : outputFileProblem(e.path);
    if (!why.empty()) return "mpr " + command_ + ": " + e.flag + ": " + why;
    for (std::size_t j = 0; j < i; ++j)
      if (sameOutputFile(entries_[j].path, e.path))
        return "mpr " + command_ + ": " + entries_[j].flag + " and " + e.flag + " name the same " +
               (e.folder || entries_[j].folder ? "path" : "file") + " '" + e.path + "'";
  }
  return "";
}

void OutputSet::createParents(const std::string& path) {
  std::error_code ec;
  const fs::path parent = fs::absolute(path, ec).lexically_normal().parent_path();
  std::vector<fs::path> missing;
  for (fs::path a = parent; !a.empty() && !fs::exists(fs::symlink_status(a, ec)); a = a.parent_path()) {
    missing.push_back(a);
    if (a == a.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (fs::create_directory(*it)) createdFolders_.push_back(it->string());
  }
}

AtomicFile& OutputSet::open(const std::string& path) {
  createParents(path);
  pending_.push_back(std::make_unique<AtomicFile>(path));
  return *pending_.back();
}

void OutputSet::write(const std::string& path, const std::string& bytes) {
  AtomicFile& f = open(path);
  f.write(bytes);
  f.finish();
}

void OutputSet::commit() {
  for (const auto& f : pending_) f->commit();
  committed_ = true;
}

}  // namespace mpr::cli
