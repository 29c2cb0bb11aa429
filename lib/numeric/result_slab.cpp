// SPDX-License-Identifier: MIT
// ResultSlab and the kept allocator's functions (result_slab.hpp,
// kept_allocator.hpp).
#include "result_slab.hpp"

#include <limits>
#include <new>

namespace cvms::detail {
namespace {

constexpr std::size_t max_bytes = std::numeric_limits<std::size_t>::max();

// x rounded up to a multiple of slab_block_alignment (a cache line: arrays
// written by different threads share none); max_bytes when that overflows.
std::size_t aligned_up(std::size_t x) noexcept {
  return x > max_bytes - (slab_block_alignment - 1)
             ? max_bytes
             : (x + slab_block_alignment - 1) & ~(slab_block_alignment - 1);
}

}  // namespace

void SlabPlan::add_bytes(std::size_t n, std::size_t size) noexcept {
  const std::size_t array = n > max_bytes / size ? max_bytes : aligned_up(n * size);
  bytes_ = array > max_bytes - bytes_ ? max_bytes : bytes_ + array;
}

std::shared_ptr<ResultSlab> ResultSlab::make(const SlabPlan& plan) {
  return std::make_shared<ResultSlab>(Token{}, plan.bytes());
}

ResultSlab::ResultSlab(Token, std::size_t bytes)
    : begin_(static_cast<std::byte*>(allocate_block(bytes, BlockLife::slab))), size_(bytes) {}

ResultSlab::~ResultSlab() { free_block(begin_, size_, BlockLife::slab); }

void* ResultSlab::carve(std::size_t bytes) noexcept {
  const std::size_t length = aligned_up(bytes);
  if (bytes == 0) return nullptr;  // an empty array is no address in the slab
  if (length > size_) {
    refused_.store(true, std::memory_order_relaxed);
    return nullptr;
  }
  // Every offset handed out is a multiple of slab_block_alignment, and begin_ is
  // aligned that far (allocate_block for BlockLife::slab).
  const std::size_t offset = used_.fetch_add(length, std::memory_order_relaxed);
  if (offset > size_ - length) {
    used_.store(size_, std::memory_order_relaxed);  // keeps the offset from wrapping on many refusals
    refused_.store(true, std::memory_order_relaxed);
    return nullptr;
  }
  carved_.fetch_add(length, std::memory_order_relaxed);
  return begin_ + offset;
}

bool ResultSlab::holds(const void* p) const noexcept {
  const auto* byte = static_cast<const std::byte*>(p);
  return size_ != 0 && byte >= begin_ && byte < begin_ + size_;
}

void* allocate_kept(ResultSlab* slab, std::size_t bytes) {
  if (slab != nullptr)
    if (void* carved = slab->carve(bytes)) return carved;
  return allocate_block(bytes, BlockLife::kept);
}

void free_kept(ResultSlab* slab, void* block, std::size_t bytes) noexcept {
  if (slab != nullptr && slab->holds(block)) return;
  free_block(block, bytes, BlockLife::kept);
}

}  // namespace cvms::detail
