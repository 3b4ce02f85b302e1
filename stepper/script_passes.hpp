#pragma once
// The passes of a GL script as `mpr step` numbers them: pass 0 is what comes
// before the first @pass (line 1 on), then one pass per @pass line.
#include <string>
#include <vector>

#include "script/gl_script.hpp"

namespace mpr {

struct ScriptPass {
  std::string label;
  int line;  // the @pass line (1 for pass 0)
};

inline std::vector<ScriptPass> scriptPasses(const Script& script) {
  std::vector<ScriptPass> passes = {{"(before the first @pass)", 1}};
  for (const ScriptCommand& c : script.commands)
    if (c.kind == ScriptCommand::Kind::Pass) passes.push_back({c.label, c.line});
  return passes;
}

}  // namespace mpr
