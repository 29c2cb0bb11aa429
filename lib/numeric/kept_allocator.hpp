// SPDX-License-Identifier: MIT
/// \file
/// The allocator of the arrays a result keeps (Mesh's connectivity among
/// them). Private to the library.
///
/// Why it has state: a sum's output is a dozen arrays of 0.2-3 MB, and each
/// from malloc, or a mapping of its own, is fresh memory at every call under
/// glibc's default policy, faulted in 4 KiB at a time (thousands of faults
/// per Sphere6 + rot. Sphere6 sum, each costing tens of microseconds on a
/// virtual machine). The library carves such a result's arrays from one
/// block on huge pages (a ResultSlab, result_slab.hpp) that each
/// array's allocator keeps alive; without a slab (every default-constructed
/// allocator, and every copy of a container: a copy never carves from the
/// slab of what it copies) an array is a block of its own, from
/// huge_page_blocks.hpp's kept blocks.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace cvms::detail {

class ResultSlab;  // result_slab.hpp

/// `bytes` bytes aligned for any fundamental type: carved from slab when it
/// is not null and has room, else a kept block of their own.
/// \throws std::bad_alloc when the system refuses.
void* allocate_kept(ResultSlab* slab, std::size_t bytes);
/// Frees what allocate_kept(slab, bytes) returned: nothing to do for what
/// was carved from slab (it goes with the slab).
void free_kept(ResultSlab* slab, void* block, std::size_t bytes) noexcept;

/// An allocator for allocate_kept, holding the slab it carves from (or none).
template <class T>
class KeptAllocator {
  static_assert(alignof(T) <= alignof(std::max_align_t), "blocks have fundamental alignment");

 public:
  using value_type = T;
  // The storage moves with the allocator, so moving a container is O(1).
  using propagate_on_container_move_assignment = std::true_type;
  using propagate_on_container_swap = std::true_type;

  KeptAllocator() = default;
  explicit KeptAllocator(std::shared_ptr<ResultSlab> slab) noexcept : slab_(std::move(slab)) {}
  template <class U>
  KeptAllocator(const KeptAllocator<U>& other) noexcept : slab_(other.slab()) {}  // NOLINT: allocator rebind

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_kept(slab_.get(), n * sizeof(T)));
  }
  void deallocate(T* block, std::size_t n) noexcept { free_kept(slab_.get(), block, n * sizeof(T)); }

  /// A copy of a container owns its storage: it neither carves from nor
  /// keeps the slab of what it copies.
  [[nodiscard]] KeptAllocator select_on_container_copy_construction() const noexcept { return {}; }

  [[nodiscard]] const std::shared_ptr<ResultSlab>& slab() const noexcept { return slab_; }

  template <class U>
  friend bool operator==(const KeptAllocator& a, const KeptAllocator<U>& b) noexcept {
    return a.slab() == b.slab();
  }

 private:
  std::shared_ptr<ResultSlab> slab_;
};

/// A vector that a result keeps: a kept block of its own, or carved from a
/// result's slab when made with its allocator (lib/numeric/result_slab.hpp).
template <class T>
using KeptVector = std::vector<T, KeptAllocator<T>>;

}  // namespace cvms::detail
