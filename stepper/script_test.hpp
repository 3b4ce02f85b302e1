#pragma once
// A GL script as a test (`mpr test`): run it, evaluate every probe in order,
// stop at the first that does not hold, and explain it with the pixel's
// history up to the probe, as `mpr step --pixel` words it.
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/profile.hpp"
#include "script/gl_script.hpp"

namespace mpr {

struct ScriptTestResult {
  std::size_t probes = 0;      // probes in the script
  std::size_t probesRun = 0;   // evaluated (all of them when the script passes)
  std::size_t glErrors = 0;    // calls GL rejected (reported, not failures)
  bool passed = true;
  // The first probe that did not hold (when !passed).
  const ScriptCommand* failed = nullptr;
  std::string message;         // the probe's explanation
  int x = -1, y = -1;          // its first failing pixel
  std::string history;         // that pixel's history up to the probe, and its values there
  int width = 0, height = 0;
  std::vector<std::uint8_t> difference;  // probeDifferenceImage at the failure (RGB, bottom-up)
};

// `script` must outlive the result (it points at the failing command).
ScriptTestResult runScriptTest(const Script& script, const HardwareProfile& profile);

}  // namespace mpr
