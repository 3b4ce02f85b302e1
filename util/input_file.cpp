#include "util/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace mpr {
namespace {

std::string sizeText(std::uint64_t bytes) {
  if (bytes >= (1u << 20)) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// Opens without blocking (a FIFO would wait for a writer) and checks what it opened.
int openChecked(const std::string& path, std::uint64_t maxBytes, const std::string& what, std::string& why) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    why = "cannot read " + what + ": " + std::strerror(errno);
    return -1;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    why = "cannot read " + what + ": " + std::strerror(errno);
  } else if (S_ISDIR(st.st_mode)) {
    why = "cannot read " + what + ": it is a folder, not a file";
  } else if (!S_ISREG(st.st_mode)) {
    why = "cannot read " + what + ": it is not a regular file (a FIFO, socket or device is refused)";
  } else if (static_cast<std::uint64_t>(st.st_size) > maxBytes) {
    why = "cannot read " + what + ": it is " + sizeText(static_cast<std::uint64_t>(st.st_size)) + ", more than the " +
          sizeText(maxBytes) + " MPR reads";
  }
  if (!why.empty()) {
    ::close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

std::string inputFileProblem(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
  std::string why;
  const int fd = openChecked(path, maxBytes, what, why);
  if (fd >= 0) ::close(fd);
  return why;
}

std::string readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
  std::string why;
  const int fd = openChecked(path, maxBytes, what, why);
  if (fd < 0) throw std::runtime_error(why);
  std::string bytes;
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) {
      const int e = errno;
      ::close(fd);
      throw std::runtime_error("cannot read " + what + ": " + std::strerror(e));
    }
    if (n == 0) break;
    // The file may grow while it is read: the limit holds for what is read.
    if (bytes.size() + static_cast<std::size_t>(n) > maxBytes) {
      ::close(fd);
      throw std::runtime_error("cannot read " + what + ": it grew past the " + sizeText(maxBytes) + " MPR reads");
    }
    bytes.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return bytes;
}

}  // namespace mpr
