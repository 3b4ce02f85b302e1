#pragma once
// A GL script's text as the parser reads it: in pieces of whole lines, so
// that a script read from its file is held a piece at a time (memory
// bounded by the buffers, not by the script's length; issue 14, "streaming
// scripts"), and the same text given as a string is one piece. The lines,
// their numbers and columns do not depend on where the pieces are cut
// (tests/pipeline/script_stream_test.cpp, ScriptText.*).
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "util/input_file.hpp"

namespace mpr {

class ScriptText {
 public:
  // `text` itself (not copied: it must outlive this), in pieces of about
  // `pieceBytes` (tests cut small ones; by default the whole text is one).
  static ScriptText ofString(std::string_view text, std::size_t pieceBytes = std::string_view::npos);
  // The script file at `path`, opened now and read a piece at a time within
  // kMaxScriptBytes; an unreadable file is a ScriptError at 0:0, as
  // readScriptText's.
  static ScriptText ofFile(const std::string& path, std::size_t pieceBytes = InputFilePieces::kPieceBytes);

  // The next piece: whole lines ending in '\n' (`last` false), or the text
  // after the last '\n', maybe empty (`last` true). False after that. A
  // UTF-8 byte-order mark at the very start of the text is not handed on.
  bool next(std::string_view& piece, bool& last);
  // Back to the start: every pass over the script (its check, its run)
  // reads it from here.
  void rewind();

 private:
  std::string path_;
  std::string_view text_;
  std::size_t pieceBytes_ = 0, at_ = 0;
  bool handedLast_ = false;
  bool atStart_ = true;  // the next piece is the text's first: a UTF-8 byte-order mark is skipped
  std::unique_ptr<InputFilePieces> file_;
};

}  // namespace mpr
