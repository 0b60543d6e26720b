// Large buffers that a sweep fills once (solve/sweep_result.hpp): a 150,001-pose result of the paper example
// is about 20 MB, about 5,000 pages of 4 KiB, and on a virtual machine the first touch of each page (a page
// fault) costs as much as solving the pose that fills it. Advising the buffer for transparent huge pages
// before its first touch lets Linux map it in 2 MiB pages instead (512 times fewer faults) when the system
// allows it (/sys/kernel/mm/transparent_hugepage/enabled = madvise or always). The advice changes nothing
// else: where it is not honoured (another system, THP off) the buffer is the same, only slower to touch.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rollkin {

/// Advises the 2 MiB-aligned interior of [data, data + bytes) for transparent huge pages (Linux); a no-op
/// for smaller buffers and elsewhere. Call it before the buffer is first written.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + huge - 1) & ~(huge - 1), last = (begin + bytes) & ~(huge - 1);
  if (data != nullptr && last > first) (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace rollkin
