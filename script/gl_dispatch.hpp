#pragma once
// A parsed script command on any GLApi: the call's arguments read back as the
// C signature's types (generated from pipeline/gl_calls.def), or a directive.
#include <span>

#include "pipeline/gl/gl_api.hpp"
#include "script/gl_script.hpp"

namespace mpr {

// Runs one command on `api`: a call, @pass, @window_map or @count_fragments
// (a snapshot does nothing here; the caller reads the buffers).
void dispatch(GLApi& api, const ScriptCommand& cmd);
// Runs one call, given by its name and arguments (dispatch's Call case).
void dispatchCall(GLApi& api, GLCall call, std::span<const ScriptArg> args);

}  // namespace mpr
