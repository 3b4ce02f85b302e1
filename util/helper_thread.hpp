#pragma once
// A thread that works behind the calling thread (the row threads of
// util/row_queue, the script reader of pipeline/script_read_ahead) gives
// way to it. On two cores the calling thread, which transforms, lights and
// sets up every draw, is a run's critical path; a helper woken for its next
// task took the core from it (on the bathroom trace the calling thread was
// preempted some 700 times a run, about 70 times with its helpers marked).
// The helpers still run whenever a core is free, so nothing waits on them
// longer; what they compute, and so every output byte, does not change.
namespace mpr {

// Marks the current thread as a helper: Linux's SCHED_BATCH (no wake-up
// preemption of the thread it shares a core with); elsewhere nothing.
void markHelperThread();

}  // namespace mpr
