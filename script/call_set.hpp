#pragma once
// The call set of the GL script language: each call's name and argument
// kinds (the call table, pipeline/gl/gl_calls.def), found by name, and the
// GL-valid arguments the emulated Iris subset leaves out.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/gl/gl_call.hpp"
#include "script/gl_script.hpp"
#include "script/script_line.hpp"

namespace mpr {

// A call as the script language knows it: its C name and argument kinds.
struct CallSpec {
  std::string_view name;
  GLCall call;
  std::string_view args;
};

// The call of that name, or null.
const CallSpec* findCall(std::string_view name);
// The known call nearest in spelling to `name` (empty when none is near).
std::string closestCallName(std::string_view name);

// a == b for a call's name: names of 8 to 16 characters (most calls) compare
// as two 8-byte words each, the first 8 characters and the last 8, instead
// of a call to memcmp for every line.
inline bool sameName(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  if (a.size() < 8 || a.size() > 16) return a == b;
  std::uint64_t a0, a1, b0, b1;
  std::memcpy(&a0, a.data(), 8);
  std::memcpy(&b0, b.data(), 8);
  std::memcpy(&a1, a.data() + a.size() - 8, 8);
  std::memcpy(&b1, b.data() + b.size() - 8, 8);
  return ((a0 ^ b0) | (a1 ^ b1)) == 0;
}

// A call line's arguments that GL accepts but the emulated subset does not
// implement (a capability, a primitive, a mode) are outside the call set:
// a ScriptError at the argument, since real GL would act on them.
void checkCallSet(const std::string& file, const CallSpec& spec, const ScriptCommand& cmd,
                  const std::vector<ScriptToken>& toks, int line);

}  // namespace mpr
