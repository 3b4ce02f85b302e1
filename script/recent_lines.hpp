#pragma once
// The call lines a trace repeats, parsed once: a mesh's vertex comes back
// with every triangle that shares it and a flat face's normal with each of
// its vertices (eight in ten of the bathroom trace's lines are byte for
// byte one of the last thousand). A call line parsed is kept by its bytes
// in a direct-mapped table; the same bytes again give the same call and
// arguments without tokens, a name lookup or numbers read. A call line's
// parse is a function of its bytes alone (its columns too), so what comes
// from the table is the command its parse would give.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "script/gl_script.hpp"

namespace mpr {

class RecentLines {
 public:
  // Lines kept: at most kMaxBytes bytes before their '\n', at most kMaxArgs
  // arguments (a vertex, a normal, a colour).
  static constexpr std::size_t kMaxBytes = 63;
  static constexpr std::size_t kMaxArgs = 4;

  struct Entry {
    alignas(16) unsigned char bytes[64];  // the line's bytes, zeros from its '\n' on
    std::uint32_t size = 0;               // 0: empty (a kept line has a call name)
    GLCall call = GLCall::Finish;
    std::uint8_t argCount = 0;
    ScriptArg args[kMaxArgs];
  };

  // The line starting at text[pos] when it was kept (null otherwise; then
  // keep() files the same line's command). Its size is the line's bytes
  // before '\n'. Needs 64 bytes from pos.
  const Entry* find(std::string_view text, std::size_t pos);
  // The command the line last looked up by find() parsed to, when it fits.
  void keep(GLCall call, std::span<const ScriptArg> args);

 private:
  static constexpr int kSlotBits = 10;
  std::unique_ptr<Entry[]> entries_;  // 2^kSlotBits, allocated at the first find
  Entry pending_;                     // the missed line's bytes (size 0: none to keep)
  Entry* pendingSlot_ = nullptr;
};

}  // namespace mpr
