// SPDX-License-Identifier: MIT
// The replaced global operator new and delete of failing_allocator.hpp.
// Blocks come from malloc (aligned ones from posix_memalign) and go back to
// free, so that AddressSanitizer's leak checker still sees every block.
#include "support/failing_allocator.hpp"

#include <stdlib.h>  // posix_memalign

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

std::atomic<bool> armed{false};
std::atomic<bool> fail_persistently{false};
std::atomic<std::uint64_t> fail_at_call{0};
std::atomic<std::uint64_t> armed_calls{0};
std::atomic<std::uint64_t> failed_calls{0};
std::atomic<std::uint64_t> all_calls{0};
std::atomic<std::uint64_t> armed_mappings{0};

// Whether this call of operator new must fail.
bool must_fail() noexcept {
  all_calls.fetch_add(1, std::memory_order_relaxed);
  if (!armed.load(std::memory_order_acquire)) return false;
  const std::uint64_t call = armed_calls.fetch_add(1) + 1;
  const std::uint64_t k = fail_at_call.load();
  if (call == k || (call > k && fail_persistently.load())) {
    failed_calls.fetch_add(1);
    return true;
  }
  return false;
}

void* allocate(std::size_t bytes, std::size_t alignment) noexcept {
  if (must_fail()) return nullptr;
  bytes = std::max<std::size_t>(bytes, 1);
  if (alignment <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) return std::malloc(bytes);
  void* block = nullptr;
  if (posix_memalign(&block, std::max(alignment, sizeof(void*)), bytes) != 0) return nullptr;
  return block;
}

void* allocate_or_throw(std::size_t bytes, std::size_t alignment) {
  void* block = allocate(bytes, alignment);
  if (block == nullptr) throw std::bad_alloc();
  return block;
}

constexpr std::size_t plain = __STDCPP_DEFAULT_NEW_ALIGNMENT__;

}  // namespace

namespace cvms::test {

FailingAllocations::FailingAllocations(std::uint64_t fail_at, bool persistent) noexcept {
  armed_calls.store(0);
  failed_calls.store(0);
  armed_mappings.store(0);
  fail_at_call.store(fail_at);
  fail_persistently.store(persistent);
  armed.store(true, std::memory_order_release);
}

FailingAllocations::~FailingAllocations() { armed.store(false, std::memory_order_release); }

std::uint64_t FailingAllocations::calls() noexcept { return armed_calls.load(); }
std::uint64_t FailingAllocations::failures() noexcept { return failed_calls.load(); }
std::uint64_t FailingAllocations::mapped_blocks() noexcept { return armed_mappings.load(); }
std::uint64_t total_allocations() noexcept { return all_calls.load(); }

}  // namespace cvms::test

// The library's hook for the blocks it maps itself (a weak no-op there).
extern "C" void cvms_huge_pages_mapped(std::ptrdiff_t bytes) noexcept {
  if (bytes > 0 && armed.load(std::memory_order_acquire)) armed_mappings.fetch_add(1);
}

// The replaceable allocation functions ([new.delete]): all of them, so that
// no form reaches the standard library's own operator new.
void* operator new(std::size_t bytes) { return allocate_or_throw(bytes, plain); }
void* operator new[](std::size_t bytes) { return allocate_or_throw(bytes, plain); }
void* operator new(std::size_t bytes, std::align_val_t alignment) {
  return allocate_or_throw(bytes, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t bytes, std::align_val_t alignment) {
  return allocate_or_throw(bytes, static_cast<std::size_t>(alignment));
}
void* operator new(std::size_t bytes, const std::nothrow_t& /*tag*/) noexcept {
  return allocate(bytes, plain);
}
void* operator new[](std::size_t bytes, const std::nothrow_t& /*tag*/) noexcept {
  return allocate(bytes, plain);
}
void* operator new(std::size_t bytes, std::align_val_t alignment, const std::nothrow_t& /*tag*/) noexcept {
  return allocate(bytes, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t bytes, std::align_val_t alignment, const std::nothrow_t& /*tag*/) noexcept {
  return allocate(bytes, static_cast<std::size_t>(alignment));
}

void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t /*bytes*/) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t /*bytes*/) noexcept { std::free(block); }
void operator delete(void* block, std::align_val_t /*alignment*/) noexcept { std::free(block); }
void operator delete[](void* block, std::align_val_t /*alignment*/) noexcept { std::free(block); }
void operator delete(void* block, std::size_t /*bytes*/, std::align_val_t /*alignment*/) noexcept {
  std::free(block);
}
void operator delete[](void* block, std::size_t /*bytes*/, std::align_val_t /*alignment*/) noexcept {
  std::free(block);
}
void operator delete(void* block, const std::nothrow_t& /*tag*/) noexcept { std::free(block); }
void operator delete[](void* block, const std::nothrow_t& /*tag*/) noexcept { std::free(block); }
void operator delete(void* block, std::align_val_t /*alignment*/, const std::nothrow_t& /*tag*/) noexcept {
  std::free(block);
}
void operator delete[](void* block, std::align_val_t /*alignment*/, const std::nothrow_t& /*tag*/) noexcept {
  std::free(block);
}
