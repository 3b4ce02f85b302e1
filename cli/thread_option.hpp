#pragma once
// --threads for the commands that draw through the emulated pipeline (gl,
// render, step, conform): a draw's rows are shared out over that many
// threads (GLContext::setThreads, drawDeferred), and with more than one
// `mpr gl` parses its script ahead on a thread of its own
// (streamScriptAhead); the bytes are the same at any count.
#include <CLI/CLI.hpp>

#include "util/worker_pool.hpp"

namespace mpr::cli {

inline void addThreadsOption(CLI::App& command, int& threads) {
  threads = hardwareThreads();
  command
      .add_option("--threads", threads,
                  "threads to share a draw's rows over (and, above one, mpr gl reads its script ahead on one; "
                  "default: every hardware thread)")
      ->check(CLI::Range(1, 256));
}

}  // namespace mpr::cli
