#pragma once
// A GL script's text cut into lines and each line into tokens
// (spec/gl-script.md): a line ends at '\n' (a '\r' before it is dropped),
// a '#' starts a comment to the line's end (a '#' inside a token too), and
// tokens are separated by spaces and tabs.
#include <cstddef>
#include <string_view>
#include <vector>

namespace mpr {

struct ScriptToken {
  std::string_view text;
  int column;  // 1-based
};

struct ScriptLine {
  std::string_view text;  // without its '\n' and a '\r' before it
  std::size_t next;       // where the next line starts; text.size() + 1 after the last
  bool last;              // the line ends at the text's end, not at a '\n'
};

// The line starting at `pos` (at most the text's size), its tokens into
// `tokens` (cleared first; the vector keeps its capacity from line to line).
// A line that lies within the text's next 64 bytes is cut from bit masks of
// those bytes (SSE2 where the machine has it); any other line by
// scriptLineOneByOne, whose result it equals.
ScriptLine nextScriptLine(std::string_view text, std::size_t pos, std::vector<ScriptToken>& tokens);
// The same cut a character at a time: the reference (tests) and the fallback.
ScriptLine scriptLineOneByOne(std::string_view text, std::size_t pos, std::vector<ScriptToken>& tokens);

}  // namespace mpr
