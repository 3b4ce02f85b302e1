#include "util/row_queue.hpp"

#include <algorithm>

#include "util/helper_thread.hpp"

namespace mpr {

RowQueue::RowQueue(int threads)
    : slots_(kCapacity), done_(static_cast<std::size_t>(std::max(1, threads)), 0) {
  for (int k = 0; k < std::max(1, threads); ++k) workers_.emplace_back([this, k] { work(k); });
}

RowQueue::~RowQueue() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;  // the threads finish what is queued first
  }
  queued_.notify_all();
  for (std::thread& t : workers_) t.join();
}

std::uint64_t RowQueue::slowest() const { return *std::min_element(done_.begin(), done_.end()); }

void RowQueue::release(std::uint64_t upTo) {
  for (; released_ < upTo; ++released_) slots_[released_ % kCapacity] = nullptr;
}

void RowQueue::push(Task task) {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    ran_.wait(lock, [this] { return pushed_ - slowest() < kCapacity; });
    release(slowest());
    slots_[pushed_ % kCapacity] = std::move(task);
    ++pushed_;
  }
  queued_.notify_all();
}

void RowQueue::wait() {
  std::exception_ptr error;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    ran_.wait(lock, [this] { return slowest() == pushed_; });
    release(pushed_);
    std::swap(error, error_);
  }
  if (error) std::rethrow_exception(error);
}

void RowQueue::work(int phase) {
  markHelperThread();  // gives way to the calling thread where the process asks it to
  const std::size_t k = static_cast<std::size_t>(phase);
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    queued_.wait(lock, [&] { return stop_ || done_[k] < pushed_; });
    if (done_[k] == pushed_) return;  // stopped with nothing left
    // The slot stays as it is until every thread has run it (push and
    // wait release only what all have run).
    const Task& task = slots_[done_[k] % kCapacity];
    lock.unlock();
    std::exception_ptr error;
    try {
      task(phase);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error && !error_) error_ = error;
    ++done_[k];
    ran_.notify_all();
  }
}

int hardwareThreads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

}  // namespace mpr
