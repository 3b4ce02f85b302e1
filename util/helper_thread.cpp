#include "util/helper_thread.hpp"

#include <atomic>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace mpr {
namespace {

std::atomic<bool> giveWay{false};

}  // namespace

void setHelperThreadsGiveWay(bool on) { giveWay.store(on, std::memory_order_relaxed); }

bool helperThreadsGiveWay() { return giveWay.load(std::memory_order_relaxed); }

void markHelperThread() {
  if (!helperThreadsGiveWay()) return;
#if defined(__linux__)
  // Allowed to any user (priority 0); where it is refused the thread runs as before.
  sched_param param{};
  param.sched_priority = 0;
  (void)pthread_setschedparam(pthread_self(), SCHED_BATCH, &param);
#endif
}

}  // namespace mpr
