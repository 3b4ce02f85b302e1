#include "pipeline/script_text.hpp"

#include <stdexcept>

#include "pipeline/gl_script.hpp"

namespace mpr {

ScriptText ScriptText::ofString(std::string_view text, std::size_t pieceBytes) {
  ScriptText t;
  t.text_ = text;
  t.pieceBytes_ = pieceBytes == 0 ? 1 : pieceBytes;
  return t;
}

ScriptText ScriptText::ofFile(const std::string& path, std::size_t pieceBytes) {
  ScriptText t;
  t.path_ = path;
  try {
    t.file_ = std::make_unique<InputFilePieces>(path, kMaxScriptBytes, "the script", pieceBytes);
  } catch (const std::runtime_error& e) {
    throw ScriptError(path, 0, 0, e.what());
  }
  return t;
}

bool ScriptText::next(std::string_view& piece, bool& last) {
  if (file_) {
    try {
      return file_->next(piece, last);
    } catch (const std::runtime_error& e) {
      throw ScriptError(path_, 0, 0, e.what());
    }
  }
  if (handedLast_) return false;
  // Up to the last '\n' within pieceBytes_ of where the last piece ended;
  // a longer line whole, to its '\n'; no '\n' left: the rest, last.
  const std::string_view rest = text_.substr(at_);
  std::size_t cut = std::string_view::npos;
  if (pieceBytes_ >= rest.size()) {
    cut = rest.rfind('\n');
  } else {
    cut = rest.rfind('\n', pieceBytes_ - 1);
    if (cut == std::string_view::npos) cut = rest.find('\n', pieceBytes_);
  }
  if (cut == std::string_view::npos) {
    piece = rest;
    at_ = text_.size();
    last = handedLast_ = true;
    return true;
  }
  piece = rest.substr(0, cut + 1);
  at_ += cut + 1;
  last = false;
  return true;
}

void ScriptText::rewind() {
  if (file_) {
    try {
      file_->rewind();
    } catch (const std::runtime_error& e) {
      throw ScriptError(path_, 0, 0, e.what());
    }
  }
  at_ = 0;
  handedLast_ = false;
}

}  // namespace mpr
