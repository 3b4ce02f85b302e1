#include "util/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
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

// read(2) of up to n bytes, retried when interrupted; throws on an error.
std::size_t readSome(int fd, char* into, std::size_t n, const std::string& what) {
  for (;;) {
    const ssize_t r = ::read(fd, into, n);
    if (r >= 0) return static_cast<std::size_t>(r);
    if (errno == EINTR || errno == EAGAIN) continue;
    const int e = errno;
    throw std::runtime_error("cannot read " + what + ": " + std::strerror(e));
  }
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
    try {
      return mpr::readSome(fd, into, n, what);
    } catch (...) {
      ::close(fd);
      throw;
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

std::size_t wholeLinesEnd(std::string_view bytes, std::size_t pieceBytes) {
  std::size_t nl = pieceBytes == 0 ? std::string_view::npos : bytes.rfind('\n', pieceBytes - 1);
  if (nl == std::string_view::npos && pieceBytes < bytes.size()) nl = bytes.find('\n', pieceBytes);
  return nl == std::string_view::npos ? 0 : nl + 1;
}

InputFilePieces::InputFilePieces(const std::string& path, std::uint64_t maxBytes, const std::string& what,
                                 std::size_t pieceBytes)
    : what_(what), maxBytes_(maxBytes), pieceBytes_(std::max<std::size_t>(pieceBytes, 1)), buffer_(pieceBytes_) {
  std::string why;
  fd_ = openChecked(path, maxBytes, what, why);
  if (fd_ < 0) throw std::runtime_error(why);
}

InputFilePieces::~InputFilePieces() {
  if (fd_ >= 0) ::close(fd_);
}

void InputFilePieces::rewind() {
  if (::lseek(fd_, 0, SEEK_SET) < 0) {
    const int e = errno;
    throw std::runtime_error("cannot read " + what_ + ": " + std::strerror(e));
  }
  begin_ = end_ = 0;
  read_ = 0;
  atEnd_ = handedLast_ = false;
}

void InputFilePieces::readMore() {
  while (end_ < buffer_.size() && !atEnd_) {
    const std::size_t n = readSome(fd_, buffer_.data() + end_, buffer_.size() - end_, what_);
    if (n == 0) {
      atEnd_ = true;
      break;
    }
    read_ += n;
    if (read_ > maxBytes_)
      throw std::runtime_error("cannot read " + what_ + ": it grew past the " + sizeText(maxBytes_) + " MPR reads");
    end_ += n;
  }
}

bool InputFilePieces::next(std::string_view& piece, bool& last) {
  if (handedLast_) return false;
  // The part line the last piece left goes to the buffer's front.
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  // A buffer grown for a long line is a piece's size again once what it
  // holds fits.
  if (buffer_.size() > pieceBytes_ && end_ <= pieceBytes_) buffer_.resize(pieceBytes_);
  for (;;) {
    readMore();
    const std::size_t cut = wholeLinesEnd(std::string_view(buffer_.data(), end_), pieceBytes_);
    if (cut > 0) {
      piece = std::string_view(buffer_.data(), cut);
      begin_ = cut;
      last = false;
      return true;
    }
    if (atEnd_) {
      piece = std::string_view(buffer_.data(), end_);
      begin_ = end_;
      last = true;
      handedLast_ = true;
      return true;
    }
    // The line goes on past the buffer: a bigger one (searched again from
    // the start: doubling, the searches add up to twice the line).
    buffer_.resize(buffer_.size() * 2);
  }
}

}  // namespace mpr
