// SPDX-License-Identifier: MIT
// allocate_block and free_block (huge_page_blocks.hpp).
#include "huge_page_blocks.hpp"

#include <cstdint>
#include <limits>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#if !defined(MADV_HUGEPAGE) && !defined(CVMS_BLOCKS_ON_HEAP_ONLY)
#define CVMS_BLOCKS_ON_HEAP_ONLY 1
#endif

#ifndef CVMS_BLOCKS_ON_HEAP_ONLY
extern "C" __attribute__((weak)) void cvms_huge_pages_mapped(std::ptrdiff_t /*bytes*/) noexcept {}
#endif

namespace cvms::detail {
namespace {

#ifndef CVMS_BLOCKS_ON_HEAP_ONLY
// The mapping's length for `bytes` (see the file comment).
// \pre bytes <= max_mapped_bytes.
std::size_t mapped_length(std::size_t bytes, BlockLife life) noexcept {
  const auto rounded = [bytes](std::size_t unit) { return (bytes + unit - 1) & ~(unit - 1); };
  const std::size_t whole_huge_pages = rounded(huge_page_bytes);
  if (life == BlockLife::scratch || (life == BlockLife::slab && whole_huge_pages - bytes <= bytes / 4))
    return whole_huge_pages;
  return rounded(static_cast<std::size_t>(sysconf(_SC_PAGESIZE)));
}

// Beyond this, the rounding and the alignment slack would overflow, or the
// hook's signed count.
constexpr std::size_t max_mapped_bytes =
    static_cast<std::size_t>(std::numeric_limits<std::ptrdiff_t>::max()) - 2 * huge_page_bytes;

// A mapping of `length` bytes starting at a 2 MiB boundary: one 2 MiB
// longer, then the parts before the boundary and after the block unmapped,
// so that every whole 2 MiB of it can be one huge page.
void* map_huge(std::size_t length) {
  const std::size_t reserved = length + huge_page_bytes;
  void* raw = mmap(nullptr, reserved, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + huge_page_bytes - 1) & ~std::uintptr_t{huge_page_bytes - 1};
  const std::size_t head = aligned - start;
  if (head != 0) munmap(raw, head);
  const std::size_t tail = reserved - head - length;
  if (tail != 0) munmap(reinterpret_cast<void*>(aligned + length), tail);
  // Only advice: without it the block is plain memory, as from malloc.
  madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
}
#endif

}  // namespace

bool huge_page_blocks_enabled() noexcept {
#ifndef CVMS_BLOCKS_ON_HEAP_ONLY
  return true;
#else
  return false;
#endif
}

bool on_huge_pages(std::size_t bytes, BlockLife life) noexcept {
  return huge_page_blocks_enabled() &&
         bytes >= (life == BlockLife::scratch ? scratch_threshold : kept_threshold);
}

void* allocate_block(std::size_t bytes, [[maybe_unused]] BlockLife life) {
#ifndef CVMS_BLOCKS_ON_HEAP_ONLY
  if (on_huge_pages(bytes, life)) {
    if (bytes > max_mapped_bytes) throw std::bad_alloc();
    void* block = map_huge(mapped_length(bytes, life));
    cvms_huge_pages_mapped(static_cast<std::ptrdiff_t>(bytes));
    return block;
  }
#endif
  if (life == BlockLife::slab) return ::operator new (bytes, std::align_val_t{slab_block_alignment});
  return ::operator new(bytes);
}

void free_block(void* block, [[maybe_unused]] std::size_t bytes, [[maybe_unused]] BlockLife life) noexcept {
  if (block == nullptr) return;
#ifndef CVMS_BLOCKS_ON_HEAP_ONLY
  if (on_huge_pages(bytes, life)) {
    munmap(block, mapped_length(bytes, life));
    cvms_huge_pages_mapped(-static_cast<std::ptrdiff_t>(bytes));
    return;
  }
#endif
  if (life == BlockLife::slab) {
    ::operator delete (block, std::align_val_t{slab_block_alignment});
    return;
  }
  ::operator delete(block);  // unsized: clang offers the sized form only with -fsized-deallocation
}

}  // namespace cvms::detail
