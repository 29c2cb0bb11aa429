// SPDX-License-Identifier: MIT
// Large arrays on transparent huge pages.
//
// Why: a call's large arrays (the quickhull's triangles and conflict lists,
// from_halfspaces' cofactor cache, an output's limb blocks) are fresh memory
// in every call. glibc maps a block of 128 KiB or more on its own, or gives
// the top of its heap back to the kernel when such a block is freed, so the
// next call faults every page in again, one 4 KiB page at a time. On the
// virtual machines this project is measured on a page fault costs 8-13 us:
// from_halfspaces on Sphere5's 5,120 facet planes took about 700 page faults
// a call, a third of its time, where qhull's qhalf on the same rows took
// about 30. One 2 MiB huge page is one fault that costs about what zeroing it
// costs (touching 4 MiB of a plain mapping took 9.9 ms there, of one advised
// for huge pages 0.28 ms).
//
// So a block of at least huge_page_threshold bytes is its own mapping,
// aligned to and a multiple of 2 MiB, advised MADV_HUGEPAGE (Linux; where the
// THP setting is "never" the advice changes nothing and 4 KiB pages fault as
// before). Smaller blocks, other platforms, and builds under AddressSanitizer
// (which checks only its own heap's blocks) take operator new. A mapped
// block is at least an eighth used; an array that is reserved large and
// filled little costs one huge page of zeroing where 4 KiB pages would have
// cost a few faults. No state is kept anywhere: which path a block took
// follows from its size alone, so that freeing finds it.
#pragma once

#include <cstddef>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

/// Called with +bytes when a block of `bytes` bytes is mapped and with
/// -bytes when it is unmapped: a no-op (a weak definition) unless a program
/// defines its own, as the benchmarks' heap counter does, so that peak heap
/// figures include the blocks that bypass operator new.
extern "C" void cvms_huge_pages_mapped(std::ptrdiff_t bytes) noexcept;

namespace cvms::detail {

/// Blocks of at least this many bytes go on huge pages (where supported).
inline constexpr std::size_t huge_page_threshold = std::size_t{1} << 18;

/// Whether a block of `bytes` bytes is its own mapping on huge pages, 2 MiB
/// aligned (else it is from operator new).
bool on_huge_pages(std::size_t bytes) noexcept;

/// A block of `bytes` bytes aligned for any fundamental type.
/// \throws std::bad_alloc when the system refuses.
void* allocate_block(std::size_t bytes);

/// Frees a block from allocate_block(bytes), with the same `bytes`.
void free_block(void* block, std::size_t bytes) noexcept;

/// A stateless allocator for allocate_block.
template <class T>
struct HugePageAllocator {
  static_assert(alignof(T) <= alignof(std::max_align_t), "blocks have fundamental alignment");
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  constexpr HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}  // NOLINT: allocator rebind

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_block(n * sizeof(T)));
  }
  void deallocate(T* block, std::size_t n) noexcept { free_block(block, n * sizeof(T)); }

  template <class U>
  friend constexpr bool operator==(const HugePageAllocator& /*a*/, const HugePageAllocator<U>& /*b*/) noexcept {
    return true;
  }
};

/// An array of n uninitialised T (trivial types only) from allocate_block:
/// nothing is written, so no page is touched before its first use.
template <class T>
class HugePageArray {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);

 public:
  explicit HugePageArray(std::size_t n) : data_(HugePageAllocator<T>().allocate(n)), size_(n) {}
  HugePageArray(HugePageArray&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  HugePageArray& operator=(HugePageArray&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    return *this;
  }
  ~HugePageArray() {
    if (data_ != nullptr) HugePageAllocator<T>().deallocate(data_, size_);
  }

  [[nodiscard]] T* data() noexcept { return data_; }
  T& operator[](std::size_t i) noexcept { return data_[i]; }

 private:
  T* data_;
  std::size_t size_;
};

/// A vector whose large capacities live on huge pages.
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace cvms::detail
