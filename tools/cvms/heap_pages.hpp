// SPDX-License-Identifier: MIT
// Transparent huge pages for the tool's heap. The exact numbers are many
// small heap blocks: `cvms check sphere6.off` touches about 18 MB of fresh
// heap, and the kernel backs it one 4 KiB page fault at a time (microseconds
// each on a virtual machine: a large share of the command's time). With huge
// pages it is one fault per 2 MiB.
//
// Like the sum limits of machine_memory.hpp, this is the tool's business,
// not the library's: a library must not change its caller's allocator.
#pragma once

namespace cvms::cli {

/// Grows the heap in one large virtual step of 256 MiB (pages are still
/// backed only when touched), asks the kernel for transparent huge pages on
/// it (madvise MADV_HUGEPAGE) and holds the heap below the first huge page,
/// so that small blocks start on huge pages. Call once, first thing in main.
/// Where the kernel or the C library cannot (not Linux with glibc, a kernel
/// without THP, a heap that cannot grow that far), at most glibc's
/// thresholds change and the heap keeps up to 256 MiB of unbacked address
/// space; with THP set to "never" the advice has no effect. Only speed
/// depends on it, never a result.
void prefer_huge_heap_pages() noexcept;

}  // namespace cvms::cli
