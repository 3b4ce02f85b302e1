#pragma once
// How the process's heap gives memory back: not at every free.

namespace mpr {

// glibc returns a freed block of more than its mmap threshold (128 KB at
// first, then as large as the largest such block freed) to the system, and
// trims the heap's top past 128 KB free; every block of set-ups, batch of
// parsed commands or row list allocated again after that is touched page by
// page anew (a page fault each, some microseconds under a hypervisor). Kept
// instead (blocks below 32 MB from the heap, the top trimmed past 512 MB
// free), they are reused: on the bathroom trace 10.4 k -> 6.7 k page faults
// and 0.66-0.70 -> 0.59-0.60 s. The peak is what the run needs either way.
// The heap is also grown once by 30 MB asked for as transparent huge pages
// (madvise, untouched): the calling thread's blocks are faulted in 2 MB at
// a time (bathroom trace 6.2 k -> 1.1 k page faults; default trace 0.09 ->
// 0.07 s; the peak a few MB higher). Every thread allocates from that one
// heap (M_ARENA_MAX 1): the script reader's batches had an arena of their
// own in 4 kB pages (1 261 -> 848 page faults, 0.405 -> 0.379 s in 11
// interleaved runs). 30 MB, not 24: the bathroom trace's heap outgrew 24
// and the rest came in 4 kB pages (848 -> 300-660 faults, 0.377 -> 0.364 s
// in 15 interleaved runs, the peak 3 MB higher); below the 32 MB mmap
// threshold, or the reserve would be a mapping of its own. Nothing outside glibc.
void keepFreedHeapMemory();

}  // namespace mpr
