// The fork-join pool the draw path shares a draw's rows out with: every
// task runs exactly once per round, on a round of any size up to the pool's
// threads, round after round.
#include "util/worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace mpr {
namespace {

TEST(WorkerPool, EveryTaskRunsOncePerRound) {
  for (int threads : {1, 2, 3, 8}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (int round = 0; round < 200; ++round) {
      const int tasks = 1 + round % threads;
      std::vector<std::atomic<int>> runs(static_cast<std::size_t>(tasks));
      pool.run(tasks, [&](int k) { ++runs[static_cast<std::size_t>(k)]; });
      for (int k = 0; k < tasks; ++k) ASSERT_EQ(runs[static_cast<std::size_t>(k)].load(), 1) << threads << " " << round << " " << k;
    }
  }
}

TEST(WorkerPool, HardwareThreadsIsAtLeastOne) { EXPECT_GE(hardwareThreads(), 1); }

}  // namespace
}  // namespace mpr
