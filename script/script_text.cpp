#include "script/script_text.hpp"

#include <stdexcept>

#include "script/gl_script.hpp"

namespace mpr {
namespace {

// The file's errors (unreadable, grown past the limit) as readScriptText
// reports them: a ScriptError at 0:0.
template <typename Read>
auto asScriptError(const std::string& path, const Read& read) {
  try {
    return read();
  } catch (const std::runtime_error& e) {
    throw ScriptError(path, 0, 0, e.what());
  }
}

// A UTF-8 byte-order mark before the first line (as some Windows editors
// save a file): not part of the script. Left in, it made line 1's first
// token "\xEF\xBB\xBFglViewport", an unknown call.
void skipByteOrderMark(std::string_view& piece) {
  if (piece.substr(0, 3) == "\xEF\xBB\xBF") piece.remove_prefix(3);
}

}  // namespace

ScriptText ScriptText::ofString(std::string_view text, std::size_t pieceBytes) {
  ScriptText t;
  t.text_ = text;
  t.pieceBytes_ = pieceBytes == 0 ? 1 : pieceBytes;
  return t;
}

ScriptText ScriptText::ofFile(const std::string& path, std::size_t pieceBytes) {
  ScriptText t;
  t.path_ = path;
  t.file_ = asScriptError(
      path, [&] { return std::make_unique<InputFilePieces>(path, kMaxScriptBytes, "the script", pieceBytes); });
  return t;
}

bool ScriptText::next(std::string_view& piece, bool& last) {
  const bool first = atStart_;
  atStart_ = false;
  if (file_) {
    if (!asScriptError(path_, [&] { return file_->next(piece, last); })) return false;
    if (first) skipByteOrderMark(piece);
    return true;
  }
  if (handedLast_) return false;
  const std::string_view rest = text_.substr(at_);
  const std::size_t cut = wholeLinesEnd(rest, pieceBytes_);
  if (cut == 0) {  // no '\n' left: the rest, last
    piece = rest;
    at_ = text_.size();
    last = handedLast_ = true;
    if (first) skipByteOrderMark(piece);
    return true;
  }
  piece = rest.substr(0, cut);
  at_ += cut;
  last = false;
  if (first) skipByteOrderMark(piece);
  return true;
}

void ScriptText::rewind() {
  if (file_) asScriptError(path_, [&] { file_->rewind(); });
  atStart_ = true;
  at_ = 0;
  handedLast_ = false;
}

}  // namespace mpr
