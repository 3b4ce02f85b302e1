#pragma once
// A fork-join pool: run(n, task) calls task(0) .. task(n - 1), task 0 on the
// caller's thread and the others on the pool's threads, and returns when all
// are done. The draw path shares a draw's rows out this way
// (GLContext::drawDeferred): each pixel is still written by one task, and
// triangles still follow each other, so every pixel sees its fragments in
// the same order and the bytes do not depend on the thread count.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mpr {

class WorkerPool {
 public:
  // `threads` >= 1 (1: run() calls every task itself).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }
  // tasks <= threads(); each task runs exactly once.
  void run(int tasks, const std::function<void(int)>& task);

 private:
  void work(int index);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const std::function<void(int)>* task_ = nullptr;
  int tasks_ = 0, pending_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
};

// The hardware's threads, at least 1 (the default of --threads).
int hardwareThreads();

}  // namespace mpr
