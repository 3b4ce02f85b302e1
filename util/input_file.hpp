#pragma once
// Reading a user's input file (a script, a scene, a mesh) without trusting
// it: only a regular file is read (a folder is not an empty input, and a FIFO
// or a device such as /dev/zero would block or never end), and only up to a
// size limit, checked before reading.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mpr {

// Why `path` cannot be read as an input of at most `maxBytes`, or empty.
// `what` names the input in the message ("the script", "the mesh file").
std::string inputFileProblem(const std::string& path, std::uint64_t maxBytes, const std::string& what);

// The file's bytes; throws std::runtime_error with inputFileProblem's
// message (or the system's) on failure.
std::string readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what);

// Where a piece of whole lines taken from the front of `bytes` ends: after
// the last '\n' within the first `pieceBytes` bytes, or, when there is none
// there, after the first '\n' (one line longer than a piece, whole); 0
// when `bytes` holds no '\n'. The one rule of InputFilePieces and of
// ScriptText's pieces of a string.
std::size_t wholeLinesEnd(std::string_view bytes, std::size_t pieceBytes);

// The same file read in pieces of whole lines, for a reader that goes
// through it line by line: memory holds one piece (and the longest line),
// not the file. Opened and checked as readInputFile does (same messages);
// the limit holds for what is read, should the file grow.
class InputFilePieces {
 public:
  static constexpr std::size_t kPieceBytes = std::size_t{1} << 18;  // 256 KiB: a piece stays in L2
  InputFilePieces(const std::string& path, std::uint64_t maxBytes, const std::string& what,
                  std::size_t pieceBytes = kPieceBytes);
  ~InputFilePieces();
  InputFilePieces(const InputFilePieces&) = delete;
  InputFilePieces& operator=(const InputFilePieces&) = delete;

  // The next piece: whole lines, each ending in '\n', within the piece size
  // (one line longer than that alone), and `last` false; or, at the end,
  // what follows the last '\n' (maybe nothing) and `last` true.
  // False after the last piece. A piece is valid until the next call.
  bool next(std::string_view& piece, bool& last);
  // Back to the file's start (the same open file, read again).
  void rewind();

 private:
  void readMore();  // fills the buffer past end_, or meets the end of the file
  std::string what_;
  std::uint64_t maxBytes_;
  std::size_t pieceBytes_;
  int fd_ = -1;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;  // the bytes read and not yet handed on
  std::uint64_t read_ = 0;           // bytes read since the start
  bool atEnd_ = false, handedLast_ = false;
};

}  // namespace mpr
