#include "cli/output_set.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "framebuffer/npy_writer.hpp"

namespace mpr::cli {
namespace fs = std::filesystem;

namespace {

std::string folderProblem(const std::string& dir) {
  if (dir.empty()) return "an empty name is not a folder to write";
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st)) return quotedPath(dir, "exists and is not a folder");
  if (!fs::exists(st) && fs::is_symlink(fs::symlink_status(dir, ec)))
    return quotedPath(dir, "is a link to a folder that does not exist");
  return existingAncestorProblem(fs::absolute(dir, ec).lexically_normal());
}

}  // namespace

OutputSet::~OutputSet() {
  pending_.clear();  // removes the temporaries first
  // Folders it created, newest first, only if empty: on failure nothing is
  // left; after the commit they hold the outputs and stay.
  for (auto it = createdFolders_.rbegin(); it != createdFolders_.rend(); ++it) {
    if (!committed_) ::unlinkat(it->parentFd, it->name.c_str(), AT_REMOVEDIR);
    it->cleanup.release();
  }
  for (const auto& [path, fd] : folderFds_) ::close(fd);
}

void OutputSet::addFile(const std::string& flag, const std::string& path) { entries_.push_back({flag, path, false, {}, {}}); }

void OutputSet::addFolder(const std::string& flag, const std::string& dir, std::vector<std::string> names,
                          std::string anySuffix) {
  entries_.push_back({flag, dir, true, std::move(names), std::move(anySuffix)});
}

void OutputSet::addInput(const std::string& what, const std::string& path) { inputs_.push_back({what, path}); }

void OutputSet::addSceneInputs(const Scene& scene) {
  if (!scene.file.empty() && scene.file.front() != '<') addInput("the scene", scene.file);  // not <default scene>
  for (const SceneObject& o : scene.objects)
    if (!o.meshFile.empty()) addInput("the mesh", o.meshFile);
}

std::string OutputSet::inputProblem(const Entry& e) const {
  for (const Input& in : inputs_) {
    const auto refuse = [&](const std::string& out) {
      return "mpr " + command_ + ": " + e.flag + ": '" + out + "' would replace " + in.what + " '" + in.path +
             "' (an output must not replace an input)";
    };
    if (!e.folder) {
      if (outputReplacesInput(e.path, in.path)) return refuse(e.path);
      continue;
    }
    for (const std::string& name : e.names)
      if (const std::string out = (fs::path(e.path) / name).string(); outputReplacesInput(out, in.path)) return refuse(out);
    // A name known only as the run goes: an input in the folder whose name
    // the folder's files may take.
    const std::string inName = fs::path(in.path).filename().string();
    if (!e.anySuffix.empty() && inName.size() > e.anySuffix.size() && inName.ends_with(e.anySuffix))
      if (const std::string out = (fs::path(e.path) / inName).string(); outputReplacesInput(out, in.path))
        return refuse(out);
  }
  return "";
}

std::string OutputSet::problem() const {
  // Each output as the files it writes: a folder's known names beside the
  // files named by flags.
  const auto files = [](const Entry& e) {
    std::vector<std::string> f;
    if (!e.folder) f.push_back(e.path);
    for (const std::string& name : e.names) f.push_back((fs::path(e.path) / name).string());
    return f;
  };
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    const std::string why = e.folder ? folderProblem(e.path) : outputFileProblem(e.path);
    if (!why.empty()) return "mpr " + command_ + ": " + e.flag + ": " + why;
    if (std::string p = inputProblem(e); !p.empty()) return p;
    for (std::size_t j = 0; j < i; ++j) {
      if (sameOutputFile(entries_[j].path, e.path))
        return "mpr " + command_ + ": " + entries_[j].flag + " and " + e.flag + " name the same " +
               (e.folder || entries_[j].folder ? "path" : "file") + " '" + e.path + "'";
      for (const std::string& a : files(entries_[j]))
        for (const std::string& b : files(e))
          if (sameOutputFile(a, b))
            return "mpr " + command_ + ": " + entries_[j].flag + " and " + e.flag + " both write '" + b + "'";
    }
  }
  return "";
}

std::runtime_error OutputSet::folderError(const fs::path& dir, int err) const {
  return std::runtime_error("cannot write in " + dir.string() + ": " + std::strerror(err));
}

int OutputSet::folderFd(const std::string& dir) {
  std::error_code ec;
  const fs::path target = fs::absolute(dir.empty() ? "." : dir, ec).lexically_normal();
  const std::string key = target.string();
  if (const auto it = folderFds_.find(key); it != folderFds_.end()) return it->second;
  // The nearest folder that exists is opened by its path (links the user
  // named are followed); every folder below it is created here and opened
  // from its parent's descriptor without following a link, so a folder
  // swapped for a link between its creation and its use is refused, never
  // written through.
  std::vector<std::string> missing;
  fs::path existing = target;
  while (!fs::exists(fs::symlink_status(existing, ec)) && existing != existing.parent_path()) {
    missing.push_back(existing.filename().string());
    existing = existing.parent_path();
  }
  int fd;
  if (const auto it = folderFds_.find(existing.string()); it != folderFds_.end()) {
    fd = it->second;
  } else {
    fd = ::open(existing.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) throw folderError(existing, errno);
    folderFds_[existing.string()] = fd;
  }
  fs::path at = existing;
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    at /= *it;
    if (::mkdirat(fd, it->c_str(), 0777) == 0) {
      // An interrupt before the commit removes it again (util/signal_cleanup).
      createdFolders_.push_back({fd, *it, SignalCleanup(fd, *it, SignalCleanup::Kind::Folder)});
    } else if (errno != EEXIST) {
      throw folderError(at, errno);
    }
    const int child = ::openat(fd, it->c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (child < 0) throw folderError(at, errno == ELOOP ? ENOTDIR : errno);
    folderFds_[at.string()] = child;
    fd = child;
  }
  return fd;
}

int OutputSet::createFolder(const std::string& dir) { return folderFd(dir); }

AtomicFile& OutputSet::open(const std::string& path) {
  const fs::path p(path);
  const int fd = folderFd(p.parent_path().string());
  pending_.push_back(std::make_unique<AtomicFile>(fd, p.filename().string(), path));
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
  // The folders hold outputs now: an interrupt from here on leaves them.
  for (CreatedFolder& c : createdFolders_) c.cleanup.release();
}

std::vector<std::string> npyDumpFileNames() {
  std::vector<std::string> names;
  for (const std::string& n : framebufferDumpNames()) names.push_back(n + ".npy");
  return names;
}

}  // namespace mpr::cli
