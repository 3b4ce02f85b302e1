#pragma once
// Vectors handed back by the thread that used them last, for the next user:
// their storage is reused (no allocation, and lines the cache may still
// hold) instead of freed on one thread and allocated afresh on another.
// At most `keep` are kept; any more are freed. Thread-safe.
#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace mpr {

template <typename T>
class VectorPool {
 public:
  explicit VectorPool(std::size_t keep) : keep_(keep) {}

  // An empty vector: one handed back (its capacity kept), or a new one.
  std::vector<T> take() {
    std::lock_guard lock(mutex_);
    if (spare_.empty()) return {};
    std::vector<T> v = std::move(spare_.back());
    spare_.pop_back();
    return v;
  }

  void give(std::vector<T>&& v) {
    v.clear();
    std::lock_guard lock(mutex_);
    if (spare_.size() < keep_) spare_.push_back(std::move(v));
  }

 private:
  std::mutex mutex_;
  std::vector<std::vector<T>> spare_;
  std::size_t keep_;
};

}  // namespace mpr
