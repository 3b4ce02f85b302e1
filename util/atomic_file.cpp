#include "util/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <system_error>

namespace mpr {
namespace fs = std::filesystem;
namespace {

std::runtime_error writeError(const std::string& path, int err) {
  std::string m = "cannot write ";
  m += path;
  m += ": ";
  m += std::strerror(err);
  return std::runtime_error(m);
}

// 16 random hex digits: the name is not guessable ahead of time (a PID is),
// and O_EXCL refuses the rare collision, which is retried.
std::string randomTag() {
  std::random_device rd;
  static const char* hex = "0123456789abcdef";
  std::string s;
  for (int i = 0; i < 4; ++i) {
    const unsigned v = rd();
    for (int k = 0; k < 4; ++k) s += hex[(v >> (4 * k)) & 15];
  }
  return s;
}

// ".NAME.tmp-RANDOM.EXT": hidden, random, the extension kept last.
std::string temporaryNameFor(const std::string& name) {
  const fs::path p(name);
  std::string t = ".";
  t += p.stem().string();
  t += ".tmp-";
  t += randomTag();
  t += p.extension().string();
  return t;
}

// The folder a target lies in, opened once: every later step is relative to
// it, so renaming or replacing the folder's path mid-write moves nothing.
int openFolderOf(const std::string& target) {
  const fs::path p(target);
  if (p.filename().empty() || p.filename() == "." || p.filename() == "..")
    throw std::runtime_error("cannot write " + quotedPath(target, "(it names no file)"));
  const fs::path parent = p.parent_path();
  const int fd = ::open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw writeError(target, errno);
  return fd;
}

std::string procPath(int fd) { return "/proc/self/fd/" + std::to_string(fd); }

}  // namespace

AtomicFile::AtomicFile(std::string target) : shown_(std::move(target)) {
  folderFd_ = openFolderOf(shown_);
  ownsFolder_ = true;
  name_ = fs::path(shown_).filename().string();
  try {
    create();
  } catch (...) {
    ::close(folderFd_);
    throw;
  }
}

AtomicFile::AtomicFile(int folderFd, const std::string& name, std::string shown)
    : shown_(std::move(shown)), name_(name), folderFd_(folderFd) {
  create();
}

void AtomicFile::create() {
  // A file with no name: nothing in the folder for another process to swap
  // while it is written. /proc must be there to give it a name later.
  fd_ = ::openat(folderFd_, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd_ >= 0 && ::access(procPath(fd_).c_str(), F_OK) == 0) {
    unnamed_ = true;
    return;
  }
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  // No O_TMPFILE here: a fresh random name, never an existing file or a link.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string tmp = temporaryNameFor(name_);
    fd_ = ::openat(folderFd_, tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      tmpName_ = tmp;
      cleanup_ = SignalCleanup(folderFd_, tmpName_, SignalCleanup::Kind::File);
      return;
    }
    if (errno != EEXIST) throw writeError(shown_, errno);
  }
  throw writeError(shown_, EEXIST);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : shown_(std::move(other.shown_)),
      name_(std::move(other.name_)),
      tmpName_(std::move(other.tmpName_)),
      folderFd_(other.folderFd_),
      ownsFolder_(other.ownsFolder_),
      fd_(other.fd_),
      unnamed_(other.unnamed_),
      finished_(other.finished_),
      committed_(other.committed_),
      cleanup_(std::move(other.cleanup_)) {
  other.fd_ = -1;
  other.folderFd_ = -1;
  other.ownsFolder_ = false;
  other.tmpName_.clear();
  other.committed_ = true;
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !tmpName_.empty()) ::unlinkat(folderFd_, tmpName_.c_str(), 0);
  cleanup_.release();
  if (fd_ >= 0) ::close(fd_);
  if (ownsFolder_ && folderFd_ >= 0) ::close(folderFd_);
}

std::string AtomicFile::descriptorPath() const {
  if (fd_ >= 0 && ::access(procPath(fd_).c_str(), F_OK) == 0) return procPath(fd_);
  return (fs::path(shown_).parent_path() / tmpName_).string();
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0 || finished_) throw writeError(shown_, EBADF);
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw writeError(shown_, n < 0 ? errno : ENOSPC);
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void AtomicFile::finish() {
  if (finished_) return;
  if (fd_ < 0) throw writeError(shown_, EBADF);
  if (::fsync(fd_) != 0) throw writeError(shown_, errno);
  finished_ = true;
  if (!unnamed_) return;
  // Named only now, complete: under a random name, so that a group's
  // renames can all follow their files' writes.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string tmp = temporaryNameFor(name_);
    cleanup_ = SignalCleanup(folderFd_, tmp, SignalCleanup::Kind::File);
    if (::linkat(AT_FDCWD, procPath(fd_).c_str(), folderFd_, tmp.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      tmpName_ = tmp;
      return;
    }
    cleanup_.release();
    if (errno != EEXIST) throw writeError(shown_, errno);
  }
  throw writeError(shown_, EEXIST);
}

void AtomicFile::commit() {
  finish();
  // The temporary's name must still hold this file: a name another process
  // replaced is not renamed over the target.
  struct stat mine {}, named {};
  if (::fstat(fd_, &mine) != 0 || ::fstatat(folderFd_, tmpName_.c_str(), &named, AT_SYMLINK_NOFOLLOW) != 0 ||
      mine.st_dev != named.st_dev || mine.st_ino != named.st_ino)
    throw std::runtime_error("cannot write " + shown_ + ": its temporary was replaced while it was written");
  if (::renameat(folderFd_, tmpName_.c_str(), folderFd_, name_.c_str()) != 0) throw writeError(shown_, errno);
  committed_ = true;
  cleanup_.release();
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  AtomicFile f(path);
  f.write(bytes);
  f.commit();
}

void writeFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<AtomicFile> pending;
  pending.reserve(files.size());
  for (const auto& [path, bytes] : files) {
    pending.emplace_back(path);
    pending.back().write(bytes);
    pending.back().finish();
  }
  for (AtomicFile& f : pending) f.commit();
}

// Built by appending (GCC 12 warns falsely, -Wrestrict, on operator+ chains).
std::string quotedPath(const std::string& path, std::string_view why) {
  std::string o = "'";
  o += path;
  o += "' ";
  o += why;
  return o;
}

std::string existingAncestorProblem(const fs::path& start) {
  std::error_code ec;
  for (fs::path a = start; !a.empty(); a = a.parent_path()) {
    const fs::file_status as = fs::status(a, ec);
    if (fs::exists(as)) return fs::is_directory(as) ? "" : quotedPath(a.string(), "is not a folder");
    // A link to nothing cannot be created as a folder: found now, not after
    // the work.
    if (fs::is_symlink(fs::symlink_status(a, ec))) return quotedPath(a.string(), "is a link to a folder that does not exist");
    if (a == a.parent_path()) break;
  }
  return "";
}

std::string outputFileProblem(const std::string& path) {
  if (path.empty()) return "an empty name is not a file to write";
  const fs::path p(path);
  if (p.filename().empty() || p.filename() == "." || p.filename() == "..")
    return quotedPath(path, "does not name a file to write");
  std::error_code ec;
  const fs::file_status st = fs::status(p, ec);
  if (fs::is_directory(st)) return quotedPath(path, "is a folder, not a file to write");
  if (fs::exists(st) && !fs::is_regular_file(st)) return quotedPath(path, "exists and is not a regular file");
  // The nearest existing ancestor must be a folder (the rest is created).
  return existingAncestorProblem(fs::absolute(p, ec).parent_path());
}

bool outputReplacesInput(const std::string& output, const std::string& input) {
  struct stat out {}, inName {}, inFile {};
  if (::lstat(output.c_str(), &out) != 0) return false;
  const bool named = ::lstat(input.c_str(), &inName) == 0;
  const bool reached = ::stat(input.c_str(), &inFile) == 0;
  return (named && out.st_dev == inName.st_dev && out.st_ino == inName.st_ino) ||
         (reached && out.st_dev == inFile.st_dev && out.st_ino == inFile.st_ino);
}

bool sameOutputFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  const fs::path pa = fs::absolute(a, ec).lexically_normal(), pb = fs::absolute(b, ec).lexically_normal();
  if (pa == pb) return true;
  // The folders with their links resolved, the names as given: a link at
  // an output's own name is replaced, not followed, so two links to one
  // file are two outputs.
  const fs::path ca = fs::weakly_canonical(pa.parent_path(), ec) / pa.filename();
  if (ec) return false;
  const fs::path cb = fs::weakly_canonical(pb.parent_path(), ec) / pb.filename();
  if (ec) return false;
  return ca == cb;
}

}  // namespace mpr
