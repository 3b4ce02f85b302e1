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

}  // namespace

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  const fs::path p(target_);
  if (p.filename().empty()) throw std::runtime_error("cannot write " + quotedPath(target_, "(it names no file)"));
  for (int attempt = 0; attempt < 100; ++attempt) {
    // Keep the extension so that OpenImageIO picks the right format.
    std::string name = ".";
    name += p.stem().string();
    name += ".tmp-";
    name += randomTag();
    name += p.extension().string();
    const std::string tmp = (p.parent_path() / name).string();
    fd_ = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      tmp_ = tmp;
      return;
    }
    if (errno != EEXIST) throw writeError(target_, errno);
  }
  throw writeError(target_, EEXIST);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)), tmp_(std::move(other.tmp_)), fd_(other.fd_), committed_(other.committed_) {
  other.fd_ = -1;
  other.tmp_.clear();
  other.committed_ = true;
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0) throw writeError(target_, EBADF);
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw writeError(target_, n < 0 ? errno : ENOSPC);
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void AtomicFile::finish() {
  if (fd_ < 0) throw writeError(target_, EBADF);
  const int fd = fd_;
  fd_ = -1;
  if (::fsync(fd) != 0) {
    const int e = errno;
    ::close(fd);
    throw writeError(target_, e);
  }
  if (::close(fd) != 0) throw writeError(target_, errno);
}

void AtomicFile::commit() {
  if (fd_ >= 0) finish();
  if (::rename(tmp_.c_str(), target_.c_str()) != 0) throw writeError(target_, errno);
  committed_ = true;
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
