#include "util/helper_thread.hpp"

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace mpr {

void markHelperThread() {
#if defined(__linux__)
  // Allowed to any user (priority 0); where it is refused the thread runs as before.
  sched_param param{};
  param.sched_priority = 0;
  (void)pthread_setschedparam(pthread_self(), SCHED_BATCH, &param);
#endif
}

}  // namespace mpr
