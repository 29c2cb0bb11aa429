// SPDX-License-Identifier: MIT
// One block for the arrays of one result, so that it faults in few pages.
//
// Why: see kept_allocator.hpp. A sum's output arrays, each its own
// block, are fresh memory at every call and fault in 4 KiB at a time; carved
// from one block mapped on huge pages (huge_page_blocks.hpp, BlockLife::slab)
// they fault once per 2 MiB.
//
// The slab is sized up front from counts the builder knows (a sum's V, E and
// F after its search), array by array (SlabPlan). Carving bumps an atomic
// offset, so threads that build parts of one result carve concurrently. A
// request that does not fit gets a block of its own, so a plan that falls
// short costs faults, never correctness. Carved memory is never freed on its
// own: the slab goes when the last allocator holding it does (each array's
// allocator shares it), so a result that drops a carved array early keeps
// its bytes until then.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>

#include "kept_allocator.hpp"
#include "huge_page_blocks.hpp"

namespace cvms::detail {

/// The bytes a slab needs for a list of arrays.
class SlabPlan {
 public:
  /// Room for n values of T.
  template <class T>
  SlabPlan& add(std::size_t n) noexcept {
    add_bytes(n, sizeof(T));
    return *this;
  }
  /// The total (saturating: absurd counts plan a slab that allocation refuses).
  [[nodiscard]] std::size_t bytes() const noexcept { return bytes_; }

 private:
  void add_bytes(std::size_t n, std::size_t size) noexcept;
  std::size_t bytes_ = 0;
};

/// One block that kept arrays are carved from (see the file comment).
class ResultSlab {
 public:
  /// A slab of plan.bytes() bytes.
  /// \throws std::bad_alloc when the system refuses.
  [[nodiscard]] static std::shared_ptr<ResultSlab> make(const SlabPlan& plan);

  ResultSlab(const ResultSlab&) = delete;
  ResultSlab& operator=(const ResultSlab&) = delete;
  ~ResultSlab();

  /// `bytes` bytes at a multiple of slab_alignment, or null when they do not
  /// fit in what is left. Safe from concurrent callers.
  [[nodiscard]] void* carve(std::size_t bytes) noexcept;
  /// Whether p points into this slab.
  [[nodiscard]] bool holds(const void* p) const noexcept;
  /// The slab's size in bytes.
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// The bytes carved so far, each array's rounded to slab_block_alignment.
  [[nodiscard]] std::size_t carved() const noexcept { return carved_.load(std::memory_order_relaxed); }
  /// Whether a request was refused (the plan fell short, or an array grew).
  [[nodiscard]] bool refused() const noexcept { return refused_.load(std::memory_order_relaxed); }

 private:
  struct Token {};  // make() only

 public:
  ResultSlab(Token, std::size_t bytes);

 private:
  std::byte* begin_;
  std::size_t size_;
  std::atomic<std::size_t> used_{0};    // the bump offset; past size_ after a refusal
  std::atomic<std::size_t> carved_{0};  // what was handed out
  std::atomic<bool> refused_{false};
};

/// A KeptAllocator<T> that carves from slab.
template <class T>
[[nodiscard]] KeptAllocator<T> carving_from(const std::shared_ptr<ResultSlab>& slab) noexcept {
  return KeptAllocator<T>(slab);
}

}  // namespace cvms::detail
