// SPDX-License-Identifier: MIT
// Large arrays on transparent huge pages.
//
// Why: a call's large arrays (the quickhull's triangles and conflict lists,
// from_halfspaces' cofactor cache, an output's planes and limbs) are fresh
// memory in every call. glibc maps a block of 128 KiB or more on its own, or
// gives the top of its heap back to the kernel when such a block is freed,
// so the next call faults every page in again, one 4 KiB page at a time. On
// a virtual machine a page fault can cost several microseconds, enough to
// be a large share of a call on a few thousand rows (from_halfspaces on
// Sphere5's 5,120 facet planes faults hundreds of pages a call, where
// qhull's qhalf on the same rows faults none). One 2 MiB huge page is one
// fault that costs about what zeroing it costs, far less than its 512 small
// pages' faults.
//
// So a large block is its own mapping, starting at a 2 MiB boundary and
// advised MADV_HUGEPAGE (Linux), of one of two kinds:
//  - Scratch, freed before the call returns: from scratch_threshold bytes
//    on, rounded up to whole 2 MiB pages, so that each is one fault. Such a
//    block is at least an eighth used; an array reserved large and filled
//    little costs one huge page of zeroing where 4 KiB pages would have cost
//    a few faults.
//  - Kept, part of a result that may live long: from 2 MiB on, rounded up
//    to the page size only, so that every whole 2 MiB of it is a huge page
//    and the tail takes what it touches, as from malloc.
//  - Slab, one block for all of a result's arrays (result_slab.hpp): kept,
//    and rounded up to whole 2 MiB pages when that adds at most a quarter,
//    so that its tail is one more fault rather than hundreds. Aligned to 64
//    bytes also when it comes from operator new. The limb arena's
//    blocks past 1 MiB are 2 MiB, wholly resident once first written: a
//    result may hold up to one partly used 2 MiB block per arena more than
//    before (a sum on two threads keeps two arenas).
// The kernel may stall such a fault to compact memory for a huge page (THP
// defrag setting "madvise", the usual default). Where THP is "never" the
// advice changes nothing and the pages fault as glibc's own mappings would;
// a program that tuned malloc to keep freed memory then faults these blocks
// in again at every call. Smaller blocks, other platforms, builds under a
// sanitizer that checks memory (which sees only its own heap) and builds
// with CVMS_HUGE_PAGE_BLOCKS=OFF (CMake) take operator new. valgrind sees
// the mappings but not their contents' use. No state is kept anywhere:
// which path a block took follows from its kind and size alone, so that
// freeing finds it.
#pragma once

#include <cstddef>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "kept_allocator.hpp"

// Sanitizers that check memory see only blocks from their own allocator;
// mapping needs Linux's MADV_HUGEPAGE. Where this is defined, every block
// comes from operator new.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_HWADDRESS__) || defined(CVMS_NO_HUGE_PAGE_BLOCKS) || \
    !defined(__linux__)
#define CVMS_BLOCKS_ON_HEAP_ONLY 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(hwaddress_sanitizer) || __has_feature(memory_sanitizer)
#define CVMS_BLOCKS_ON_HEAP_ONLY 1
#endif
#endif

/// Internal to cvms (not an API): called with +bytes when a block of
/// `bytes` bytes is mapped and with -bytes when it is unmapped. A weak no-op
/// unless a program defines its own, as the benchmarks' heap counter does,
/// so that peak heap figures include the blocks that bypass operator new.
extern "C" void cvms_huge_pages_mapped(std::ptrdiff_t bytes) noexcept;

namespace cvms::detail {

/// How long a block lives (see the file comment).
enum class BlockLife { scratch, kept, slab };

/// The size of a huge page (x86-64 and 4 KiB-page arm64 Linux).
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;
/// Scratch blocks of at least this many bytes go on huge pages.
inline constexpr std::size_t scratch_threshold = std::size_t{1} << 18;
/// Kept and slab blocks of at least this many bytes (one huge page) do.
inline constexpr std::size_t kept_threshold = huge_page_bytes;
/// The alignment of slab blocks.
inline constexpr std::size_t slab_block_alignment = 64;

/// Whether this build maps large blocks itself at all.
bool huge_page_blocks_enabled() noexcept;

/// Whether a block of `bytes` bytes is its own mapping, 2 MiB aligned (else
/// it is from operator new).
bool on_huge_pages(std::size_t bytes, BlockLife life) noexcept;

/// A block of `bytes` bytes aligned for any fundamental type.
/// \throws std::bad_alloc when the system refuses.
void* allocate_block(std::size_t bytes, BlockLife life);

/// Frees a block from allocate_block(bytes, life), with the same arguments.
void free_block(void* block, std::size_t bytes, BlockLife life) noexcept;

/// A stateless allocator for allocate_block.
template <class T, BlockLife Life>
struct HugePageAllocator {
  static_assert(alignof(T) <= alignof(std::max_align_t), "blocks have fundamental alignment");
  using value_type = T;
  template <class U>
  struct rebind {
    using other = HugePageAllocator<U, Life>;
  };

  HugePageAllocator() = default;
  template <class U>
  constexpr HugePageAllocator(const HugePageAllocator<U, Life>& /*other*/) noexcept {
  }  // NOLINT: allocator rebind

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_block(n * sizeof(T), Life));
  }
  void deallocate(T* block, std::size_t n) noexcept { free_block(block, n * sizeof(T), Life); }

  template <class U>
  friend constexpr bool operator==(const HugePageAllocator& /*a*/,
                                   const HugePageAllocator<U, Life>& /*b*/) noexcept {
    return true;
  }
};

/// A vector for a call's scratch.
template <class T>
using ScratchVector = std::vector<T, HugePageAllocator<T, BlockLife::scratch>>;

/// An array of n uninitialised T (trivial types only) from allocate_block:
/// nothing is written, so that no page is touched before its first use.
template <class T, BlockLife Life>
class HugePageArray {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);

 public:
  explicit HugePageArray(std::size_t n) : data_(Allocator().allocate(n)), size_(n) {}
  HugePageArray(HugePageArray&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  HugePageArray& operator=(HugePageArray&& other) noexcept {
    HugePageArray taken(std::move(other));  // this array's old block is freed with `taken`
    std::swap(data_, taken.data_);
    std::swap(size_, taken.size_);
    return *this;
  }
  HugePageArray(const HugePageArray&) = delete;
  HugePageArray& operator=(const HugePageArray&) = delete;
  ~HugePageArray() {
    if (data_ != nullptr) Allocator().deallocate(data_, size_);
  }

  [[nodiscard]] T* data() noexcept { return data_; }
  T& operator[](std::size_t i) noexcept { return data_[i]; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }

 private:
  using Allocator = HugePageAllocator<T, Life>;
  T* data_;
  std::size_t size_;
};

}  // namespace cvms::detail
