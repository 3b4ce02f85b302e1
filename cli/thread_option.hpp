#pragma once
// --threads for the commands that draw through the emulated pipeline (gl,
// render, step, conform): with more than one, that many threads draw the
// framebuffer's rows behind the calls (DrawStage::setThreads, drawDeferred),
// `mpr gl` parses its script ahead on a thread of its own
// (streamScriptAhead); the bytes are the same at any count.
#include <CLI/CLI.hpp>

#include "util/row_queue.hpp"

namespace mpr::cli {

inline void addThreadsOption(CLI::App& command, int& threads) {
  threads = hardwareThreads();
  command
      .add_option("--threads", threads,
                  "threads that draw the framebuffer's rows behind the calls (and, above one, mpr gl reads its script ahead on one; "
                  "default: every hardware thread)")
      ->check(CLI::Range(1, 256));
}

}  // namespace mpr::cli
