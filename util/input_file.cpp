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
int openChecked(const std::string& path, std::uint64_t maxBytes, const std::string& what, std::string& why,
                std::uint64_t* size = nullptr) {
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
  if (size) *size = static_cast<std::uint64_t>(st.st_size);
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
  std::uint64_t size = 0;
  const int fd = openChecked(path, maxBytes, what, why, &size);
  if (fd < 0) throw std::runtime_error(why);
  // Read straight into a string of the size fstat gave: through a 64 KiB
  // buffer appended to a growing string, a 124 MB trace was copied about
  // three times and a tenth of reading it was memmove and page faults.
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  const auto readSome = [&](char* into, std::size_t n) -> std::size_t {
    for (;;) {
      const ssize_t r = ::read(fd, into, n);
      if (r >= 0) return static_cast<std::size_t>(r);
      if (errno == EINTR || errno == EAGAIN) continue;
      const int e = errno;
      ::close(fd);
      throw std::runtime_error("cannot read " + what + ": " + std::strerror(e));
    }
  };
  while (got < bytes.size()) {
    const std::size_t n = readSome(bytes.data() + got, bytes.size() - got);
    if (n == 0) break;
    got += n;
  }
  bytes.resize(got);
  // Then on to the end, should the file have grown while it was read (or
  // had no size to stat, as procfs files): the limit holds for what is read.
  char chunk[1 << 16];
  for (;;) {
    const std::size_t n = readSome(chunk, sizeof chunk);
    if (n == 0) break;
    if (bytes.size() + n > maxBytes) {
      ::close(fd);
      throw std::runtime_error("cannot read " + what + ": it grew past the " + sizeText(maxBytes) + " MPR reads");
    }
    bytes.append(chunk, n);
  }
  ::close(fd);
  return bytes;
}

}  // namespace mpr
