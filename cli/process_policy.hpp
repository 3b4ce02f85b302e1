#pragma once
// The mpr executable's process policy: tuning of the whole process (its
// heap, how its threads share the cores) that the executable chooses at
// start-up and the libraries never do: a program that links MPR::gl keeps
// its own malloc settings and thread scheduling.
namespace mpr::cli {

// Called once, first thing in main, before any thread starts:
// - freed heap memory kept for reuse (glibc's mallopt: fixed mmap and trim
//   thresholds, one arena) and the heap grown once as transparent huge pages,
//   so that blocks freed and allocated again (set-ups, batches of parsed
//   commands, row lists, framebuffers) are reused, not faulted in again page
//   by page;
// - the row threads and the script reader give way to the calling thread
//   (util/helper_thread: SCHED_BATCH on Linux).
// Neither changes what is computed: every output byte is the same without it.
void applyProcessPolicy();

}  // namespace mpr::cli
