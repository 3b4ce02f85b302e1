#pragma once
// streamScript with the reading on a thread of its own: a helper thread
// parses the (already checked) script into batches of commands while the
// caller's thread hands them to `sink` in order, so a script's parsing
// overlaps its execution (on a multi-core machine the reading of a long
// trace is most of its time, llvmpipe's and MPR's alike). The commands,
// their order and what reaches the sink are streamScript's exactly; memory
// stays bounded (a few batches in flight). A ScriptError the reader meets
// is thrown after the commands before it; when the sink throws, the reader
// stops and the exception goes on.
#include <functional>
#include <string_view>

#include "pipeline/gl_script.hpp"
#include "pipeline/script_text.hpp"

namespace mpr {

void streamScriptAhead(std::string_view text, const Script& header, const std::function<void(ScriptCommand&&)>& sink);
// The same, the text read (a file: from its start, a piece at a time) on
// the reading thread.
void streamScriptAhead(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink);

}  // namespace mpr
