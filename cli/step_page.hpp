#pragma once
// `mpr step INPUT --html DIR`: runs a script once, recording at every pass
// end its GL state and its buffers (as deltas, cli/frame_delta_encoder) and
// every pixel's history (cli/pixel_history_encoder), and writes a static page
// that opens from the file system: index.html, the page's script and style
// (web/), and the recording as three .js files (no fetch: browsers refuse
// file:// requests).
#include <chrono>
#include <cstddef>
#include <string>

#include "framebuffer/profile.hpp"
#include "script/gl_script.hpp"

namespace mpr::cli {

// The page's <meta name="generator">: how an earlier page is recognised.
inline constexpr const char* kStepPageGenerator = "mpr step";

struct StepPageOptions {
  std::string dir;
  std::string input;  // as the user named it, for the page and its `mpr step --pixel` hint
  std::size_t historyBudgetBytes = std::size_t{64} << 20;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();  // for the time reported
};

// Writes the page; returns the exit status, having reported any error.
int writeStepPage(const Script& script, const HardwareProfile& profile, const StepPageOptions& o);

}  // namespace mpr::cli
