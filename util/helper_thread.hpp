#pragma once
// A thread that works behind the calling thread (the row threads of
// util/row_queue, the script reader of script/script_read_ahead) may give
// way to it. On two cores the calling thread, which transforms, lights and
// sets up every draw, is a run's critical path; a helper woken for its next
// task took the core from it. Marked, the helpers still run whenever a core
// is free, so nothing waits on them longer; what they compute, and so every
// output byte, does not change.
//
// Whether they give way is process policy, not the library's: how a host
// program's threads share its cores is the host program's choice. Off by
// default, so a library user's helpers are scheduled as the thread that
// started them; the mpr executable turns it on at start-up
// (cli/process_policy).
namespace mpr {

// Process policy: helpers started from now on give way to the calling
// thread (on) or are scheduled as the thread that started them (off, the
// default). Set it once, before any helper starts; a helper already running
// keeps what it was given.
void setHelperThreadsGiveWay(bool on);
bool helperThreadsGiveWay();

// Called by a helper as it starts: with the policy on, Linux's SCHED_BATCH
// (no wake-up preemption of the thread it shares a core with; elsewhere
// nothing); with it off, nothing.
void markHelperThread();

}  // namespace mpr
