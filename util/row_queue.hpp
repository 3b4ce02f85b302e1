#pragma once
// Work on a framebuffer's rows, done behind the caller on threads of its own:
// push(task) queues a task and returns; each of the queue's n threads runs
// every task, in the order they were pushed, thread k for the rows y with
// y mod n == k. A pixel belongs to one thread, and that thread sees the
// tasks touching it in submission order, so the bytes do not depend on n;
// llvmpipe bins its triangles into tiles, each tile rasterised by one thread
// in submission order, for the same end (lp_setup_tri.c, lp_rast.c).
// The caller goes on (transforming, lighting, setting up the next draw)
// while the threads draw; wait() is where it reads what they wrote.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mpr {

class RowQueue {
 public:
  // task(k): the rows y with y mod threads() == k. Copied into the queue, so
  // it must own (or share) what it reads.
  using Task = std::function<void(int phase)>;

  // `threads` >= 1 threads of the queue's own (the caller's thread runs none).
  explicit RowQueue(int threads);
  ~RowQueue();  // runs what is queued, then stops the threads
  RowQueue(const RowQueue&) = delete;
  RowQueue& operator=(const RowQueue&) = delete;

  int threads() const { return static_cast<int>(workers_.size()); }
  // Returns at once, unless kCapacity tasks are still running or waiting:
  // then when the oldest has run on every thread (memory stays bounded).
  void push(Task task);
  // Returns when every task pushed has run on every thread, and throws what
  // a task threw since the last wait() (the first one; the others ran on).
  void wait();

  static constexpr std::uint64_t kCapacity = 64;

 private:
  void work(int phase);
  std::uint64_t slowest() const;  // tasks every thread has run (mutex_ held)
  void release(std::uint64_t upTo);  // destroys the tasks before upTo every thread has run (mutex_ held)

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable queued_, ran_;
  std::vector<Task> slots_;          // task i in slot i mod kCapacity
  std::vector<std::uint64_t> done_;  // tasks thread k has run
  std::uint64_t pushed_ = 0, released_ = 0;
  std::exception_ptr error_;
  bool stop_ = false;
};

// The hardware's threads, at least 1 (the default of --threads).
int hardwareThreads();

}  // namespace mpr
