// The queue the draw path hands its rows to: every task runs once on every
// thread, with its phase, in the order pushed on each thread; push returns
// before the task has run; wait() waits for all of it and throws what a task
// threw; more than kCapacity tasks in flight make push wait instead of
// queueing without bound; its threads give way to the calling thread where
// the process asks for it, and only there.
#include "util/row_queue.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <stdexcept>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sched.h>
#endif

#include "util/helper_thread.hpp"

namespace mpr {
namespace {

TEST(RowQueue, EveryTaskRunsOnEveryThreadInOrder) {
  for (int threads : {1, 2, 3, 8}) {
    RowQueue queue(threads);
    EXPECT_EQ(queue.threads(), threads);
    // seen[k]: the tasks thread k ran, in its order (written by thread k alone).
    std::vector<std::vector<int>> seen(static_cast<std::size_t>(threads));
    const int tasks = 500;  // several times the capacity
    for (int t = 0; t < tasks; ++t)
      queue.push([&seen, t](int k) { seen[static_cast<std::size_t>(k)].push_back(t); });
    queue.wait();
    for (int k = 0; k < threads; ++k) {
      ASSERT_EQ(seen[static_cast<std::size_t>(k)].size(), static_cast<std::size_t>(tasks)) << threads << " " << k;
      for (int t = 0; t < tasks; ++t) ASSERT_EQ(seen[static_cast<std::size_t>(k)][static_cast<std::size_t>(t)], t);
    }
  }
}

TEST(RowQueue, PushReturnsBeforeTheTaskRunsAndWaitWaitsForIt) {
  RowQueue queue(2);
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  std::atomic<int> ran{0};
  queue.push([gate, &ran](int) {
    gate.wait();
    ++ran;
  });
  EXPECT_EQ(ran.load(), 0);  // push came back while both threads are held
  release.set_value();
  queue.wait();
  EXPECT_EQ(ran.load(), 2);
}

TEST(RowQueue, PushWaitsWhenCapacityTasksAreInFlight) {
  RowQueue queue(2);
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  for (std::uint64_t t = 0; t < RowQueue::kCapacity; ++t) queue.push([gate](int) { gate.wait(); });
  std::atomic<bool> pushed{false};
  std::thread producer([&] {
    queue.push([](int) {});
    pushed = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(pushed.load());  // the oldest task has not run: no room
  release.set_value();
  producer.join();
  EXPECT_TRUE(pushed.load());
  queue.wait();
}

TEST(RowQueue, WaitThrowsWhatATaskThrewAndTheQueueGoesOn) {
  RowQueue queue(3);
  std::atomic<int> after{0};
  queue.push([](int k) {
    if (k == 1) throw std::runtime_error("row 1");
  });
  queue.push([&after](int) { ++after; });
  EXPECT_THROW(queue.wait(), std::runtime_error);
  EXPECT_EQ(after.load(), 3);
  EXPECT_NO_THROW(queue.wait());  // thrown once
}

TEST(RowQueue, DestructionRunsWhatIsQueued) {
  std::atomic<int> ran{0};
  {
    RowQueue queue(2);
    for (int t = 0; t < 100; ++t) queue.push([&ran](int) { ++ran; });
  }
  EXPECT_EQ(ran.load(), 200);
}

// The helper-thread policy (util/helper_thread) set for a test and put back
// after it: a process policy, and in the sanitizer build every test of the
// binary runs in one process.
class HelperPolicy {
 public:
  explicit HelperPolicy(bool giveWay) : before_(helperThreadsGiveWay()) { setHelperThreadsGiveWay(giveWay); }
  ~HelperPolicy() { setHelperThreadsGiveWay(before_); }
  HelperPolicy(const HelperPolicy&) = delete;
  HelperPolicy& operator=(const HelperPolicy&) = delete;

 private:
  bool before_;
};

#if defined(__linux__)
// The scheduling policy of each of a fresh queue's threads.
std::vector<int> queueThreadPolicies(int threads) {
  RowQueue queue(threads);
  std::vector<int> policies(static_cast<std::size_t>(threads), -1);
  queue.push([&](int k) { policies[static_cast<std::size_t>(k)] = sched_getscheduler(0); });
  queue.wait();
  return policies;
}
#endif

// With the process policy on (the mpr executable turns it on at start-up,
// cli/process_policy), the queue's threads are helpers: on Linux they run
// under SCHED_BATCH, the calling thread as it was.
TEST(RowQueue, ItsThreadsGiveWayToTheCallingThreadWhereTheProcessAsks) {
#if defined(__linux__)
  const HelperPolicy on(true);
  int marked = -1;
  std::thread probe([&] {
    markHelperThread();
    marked = sched_getscheduler(0);
  });
  probe.join();
  if (marked != SCHED_BATCH) GTEST_SKIP() << "this system refuses SCHED_BATCH";
  const int caller = sched_getscheduler(0);
  for (int p : queueThreadPolicies(3)) EXPECT_EQ(p, SCHED_BATCH);
  EXPECT_EQ(sched_getscheduler(0), caller);
  EXPECT_NE(caller, SCHED_BATCH);
#else
  GTEST_SKIP() << "helpers are marked on Linux only";
#endif
}

// A library user's process (the policy as the library leaves it): the
// queue's threads are scheduled as the thread that started them.
TEST(RowQueue, ByDefaultItsThreadsAreScheduledAsTheCallingThread) {
  EXPECT_FALSE(helperThreadsGiveWay());
#if defined(__linux__)
  const int caller = sched_getscheduler(0);
  ASSERT_NE(caller, SCHED_BATCH) << "the test runs under SCHED_BATCH: it cannot tell a marked thread from an unmarked one";
  for (int p : queueThreadPolicies(3)) EXPECT_EQ(p, caller);
  // Turned on and off again: threads started after that are as before.
  {
    const HelperPolicy on(true);
  }
  for (int p : queueThreadPolicies(2)) EXPECT_EQ(p, caller);
#endif
}

// The default of --threads: the hardware's threads as the C++ library
// reports them, or 1 where it cannot tell (it reports 0).
TEST(RowQueue, HardwareThreadsAreTheReportedCountOrOne) {
  const unsigned reported = std::thread::hardware_concurrency();
  EXPECT_EQ(hardwareThreads(), reported == 0 ? 1 : static_cast<int>(reported));
}

}  // namespace
}  // namespace mpr
