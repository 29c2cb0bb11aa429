// SPDX-License-Identifier: MIT
#include "heap_counter.hpp"

#include <gmp.h>

#include <cstdlib>
#include <new>

#include "huge_page_blocks.hpp"

namespace cvms_bench {
namespace {

// Trivial thread-locals: no initialisation guard, safe to touch from
// operator new at any point of a thread's life.
thread_local std::int64_t live = 0;
thread_local std::int64_t base = 0;
thread_local std::int64_t peak = 0;

void count_alloc(std::size_t n) noexcept {
  live += static_cast<std::int64_t>(n);
  if (live > peak) peak = live;
}
void count_free(std::size_t n) noexcept { live -= static_cast<std::int64_t>(n); }

// operator delete is not always given the size, so each block carries it in
// a header of `align` bytes in front of the user pointer (which keeps the
// user pointer aligned as requested).
constexpr std::size_t kHeader = alignof(std::max_align_t);

void* allocate(std::size_t n, std::size_t align) noexcept {
  void* block = nullptr;
  if (align <= kHeader) {
    align = kHeader;
    block = std::malloc(n + align);
  } else {
    const std::size_t total = (n + align + align - 1) / align * align;  // aligned_alloc wants a multiple
    block = std::aligned_alloc(align, total);
  }
  if (block == nullptr) return nullptr;
  auto* user = static_cast<unsigned char*>(block) + align;
  *reinterpret_cast<std::size_t*>(user - sizeof(std::size_t)) = n;
  count_alloc(n);
  return user;
}

void deallocate(void* p, std::size_t align) noexcept {
  if (p == nullptr) return;
  if (align < kHeader) align = kHeader;
  auto* user = static_cast<unsigned char*>(p);
  count_free(*reinterpret_cast<std::size_t*>(user - sizeof(std::size_t)));
  std::free(user - align);
}

void* allocate_or_throw(std::size_t n, std::size_t align) {
  // Zero-byte requests must return distinct pointers: allocate one byte.
  if (void* p = allocate(n == 0 ? 1 : n, align)) return p;
  throw std::bad_alloc();
}

// GMP passes the sizes itself: no header needed.
void* gmp_alloc(std::size_t n) {
  void* p = std::malloc(n);
  if (p == nullptr) std::abort();  // GMP cannot handle a failed allocation either
  count_alloc(n);
  return p;
}
void* gmp_realloc(void* p, std::size_t old_size, std::size_t new_size) {
  void* q = std::realloc(p, new_size);
  if (q == nullptr) std::abort();
  count_free(old_size);
  count_alloc(new_size);
  return q;
}
void gmp_free(void* p, std::size_t n) {
  if (p == nullptr) return;
  count_free(n);
  std::free(p);
}

// Before main: GMP numbers made earlier (static initialisers elsewhere)
// came from malloc with the same sizes, so freeing them here stays correct.
[[maybe_unused]] const bool gmp_installed = [] {
  mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
  return true;
}();

}  // namespace

void reset_heap_peak() noexcept {
  base = live;
  peak = live;
}
std::size_t peak_heap_bytes() noexcept { return static_cast<std::size_t>(peak - base); }
std::int64_t live_heap_bytes() noexcept { return live - base; }

}  // namespace cvms_bench

// The library's blocks on huge pages bypass operator new
// (lib/numeric/huge_page_blocks.hpp): counted here as heap all the same.
extern "C" void cvms_huge_pages_mapped(std::ptrdiff_t bytes) noexcept {
  if (bytes >= 0)
    cvms_bench::count_alloc(static_cast<std::size_t>(bytes));
  else
    cvms_bench::count_free(static_cast<std::size_t>(-bytes));
}

using cvms_bench::allocate;
using cvms_bench::allocate_or_throw;
using cvms_bench::deallocate;
using cvms_bench::kHeader;

void* operator new(std::size_t n) { return allocate_or_throw(n, kHeader); }
void* operator new[](std::size_t n) { return allocate_or_throw(n, kHeader); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return allocate(n == 0 ? 1 : n, kHeader);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return allocate(n == 0 ? 1 : n, kHeader);
}
void* operator new(std::size_t n, std::align_val_t a) {
  return allocate_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return allocate_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n == 0 ? 1 : n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n == 0 ? 1 : n, static_cast<std::size_t>(a));
}

void operator delete(void* p) noexcept { deallocate(p, kHeader); }
void operator delete[](void* p) noexcept { deallocate(p, kHeader); }
void operator delete(void* p, std::size_t) noexcept { deallocate(p, kHeader); }
void operator delete[](void* p, std::size_t) noexcept { deallocate(p, kHeader); }
void operator delete(void* p, const std::nothrow_t&) noexcept { deallocate(p, kHeader); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { deallocate(p, kHeader); }
void operator delete(void* p, std::align_val_t a) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete[](void* p, std::align_val_t a) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete(void* p, std::size_t, std::align_val_t a) noexcept {
  deallocate(p, static_cast<std::size_t>(a));
}
void operator delete[](void* p, std::size_t, std::align_val_t a) noexcept {
  deallocate(p, static_cast<std::size_t>(a));
}
void operator delete(void* p, std::align_val_t a, const std::nothrow_t&) noexcept {
  deallocate(p, static_cast<std::size_t>(a));
}
void operator delete[](void* p, std::align_val_t a, const std::nothrow_t&) noexcept {
  deallocate(p, static_cast<std::size_t>(a));
}
