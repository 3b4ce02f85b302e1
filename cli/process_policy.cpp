#include "cli/process_policy.hpp"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#endif

#include "util/helper_thread.hpp"

namespace mpr::cli {
namespace {

// How the heap gives memory back: not at every free. glibc returns a freed
// block of more than its mmap threshold (128 KB at first, then as large as
// the largest such block freed) to the system, and trims the heap's top past
// 128 KB free; every block of set-ups, batch of parsed commands or row list
// allocated again after that is touched page by page anew, a page fault
// each. Kept instead (blocks below 32 MB from the heap, the top trimmed past
// 512 MB free), they are reused; the peak is what the run needs either way.
// Nothing outside glibc. (Measurements: docs/dev/draw-path.md, "Freed memory kept".)
void keepFreedHeapMemory() {
#if defined(__GLIBC__)
  // Setting either fixes it (glibc's dynamic threshold stops moving).
  constexpr std::size_t kMmapThreshold = 32 * 1024 * 1024;
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
  // One arena for every thread: the script reader's batches then come from
  // the heap grown below, in 2 MB pages, not from an arena of its own
  // faulted in 4 kB at a time.
  mallopt(M_ARENA_MAX, 1);
#if defined(MADV_HUGEPAGE)
  // The heap grown once, its pages asked for as 2 MB pages (transparent
  // huge pages, where the kernel offers them on request), and given back
  // to the heap's top, where the trim threshold keeps it: what the calling
  // thread allocates later (set-ups, framebuffers) is faulted in 2 MB at a
  // time, not 4 kB. Nothing is touched here, so memory only grows with what
  // is used. 30 MB holds what a large trace's heap grows to (past it, the
  // rest comes in 4 kB pages), and stays below the mmap threshold, or the
  // reserve would be a mapping of its own, not the heap.
  constexpr std::size_t kHeapReserve = 30 * 1024 * 1024, kHugePage = 2 * 1024 * 1024;
  static_assert(kHeapReserve < kMmapThreshold, "at the threshold the reserve would be a mapping, not the heap");
  if (void* block = std::malloc(kHeapReserve)) {
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t end = (start + kHeapReserve) & ~(kHugePage - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    std::free(block);
  }
#endif
#endif
}

}  // namespace

void applyProcessPolicy() {
  keepFreedHeapMemory();
  setHelperThreadsGiveWay(true);
}

}  // namespace mpr::cli
