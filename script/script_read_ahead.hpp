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
#include <span>
#include <string_view>

#include "script/gl_script.hpp"
#include "script/script_text.hpp"

namespace mpr {

void streamScriptAhead(std::string_view text, const Script& header, const std::function<void(ScriptCommand&&)>& sink);
// The same, the text read (a file: from its start, a piece at a time) on
// the reading thread.
void streamScriptAhead(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink);
// The same, a call offered to `call` first as its parts (no command is made
// for it: on the bathroom trace the unpacking of its three million calls into
// commands was a fifth of the calling thread's instructions); where `call`
// returns false, the command goes to `sink` as before.
using PackedCallSink = std::function<bool(GLCall call, int line, std::span<const ScriptArg> args)>;
void streamScriptAhead(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink,
                       const PackedCallSink& call);

}  // namespace mpr
