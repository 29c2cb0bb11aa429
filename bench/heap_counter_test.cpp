// SPDX-License-Identifier: MIT
// Checks that the heap counter behind the benchmarks' peak_heap_bytes sees
// known allocations: a vector's buffer (operator new), an over-aligned
// object (aligned operator new) and a large GMP integer (its limbs come from
// the GMP allocation functions), and a large vector on the library's huge
// pages (past operator new: huge_page_blocks.hpp). Exits non-zero on the
// first failure.
#include "heap_counter.hpp"

#include <gmpxx.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include "huge_page_blocks.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "FAILED: %s (peak %zu, live %lld)\n", what, cvms_bench::peak_heap_bytes(),
                 static_cast<long long>(cvms_bench::live_heap_bytes()));
    ++failures;
  }
}

// Keeps the optimiser from removing an allocation that is never read.
void* volatile sink = nullptr;

struct alignas(256) Overaligned {
  unsigned char bytes[4096];
};

}  // namespace

int main() {
  constexpr std::size_t kMiB = 1 << 20;

  cvms_bench::reset_heap_peak();
  check(cvms_bench::peak_heap_bytes() == 0, "peak is zero right after a reset");
  {
    std::vector<unsigned char> buffer(kMiB, 1);
    sink = buffer.data();
    check(cvms_bench::live_heap_bytes() >= static_cast<std::int64_t>(kMiB), "a 1 MiB vector is live");
  }
  check(cvms_bench::peak_heap_bytes() >= kMiB, "the 1 MiB vector reached the peak");
  check(cvms_bench::peak_heap_bytes() < 2 * kMiB, "nothing else of that size was counted");
  check(cvms_bench::live_heap_bytes() == 0, "freeing the vector returns the live bytes to zero");

  cvms_bench::reset_heap_peak();
  {
    cvms::detail::ScratchVector<unsigned char> large(4 * kMiB, 1);
    sink = large.data();
    check(cvms_bench::live_heap_bytes() >= static_cast<std::int64_t>(4 * kMiB),
          "a 4 MiB vector on huge pages is live");
  }
  check(cvms_bench::peak_heap_bytes() >= 4 * kMiB, "that vector reached the peak");
  check(cvms_bench::live_heap_bytes() == 0, "freeing that vector returns the live bytes to zero");

  cvms_bench::reset_heap_peak();
  {
    auto object = std::make_unique<Overaligned>();
    sink = object.get();
    check(reinterpret_cast<std::uintptr_t>(object.get()) % 256 == 0, "aligned new keeps the alignment");
  }
  check(cvms_bench::peak_heap_bytes() >= sizeof(Overaligned), "the over-aligned object was counted");
  check(cvms_bench::live_heap_bytes() == 0, "aligned delete uncounts it");

  cvms_bench::reset_heap_peak();
  {
    mpz_class big = 1;
    big <<= 8 * kMiB;  // 2^(8 Mi): 1 MiB of limbs
    sink = big.get_mpz_t();
    check(cvms_bench::live_heap_bytes() >= static_cast<std::int64_t>(kMiB), "GMP limbs are live");
  }
  check(cvms_bench::peak_heap_bytes() >= kMiB, "GMP limbs reached the peak");
  check(cvms_bench::live_heap_bytes() == 0, "mpz_clear uncounts the limbs");

  if (failures == 0) std::puts("heap counter: all checks passed");
  return failures == 0 ? 0 : 1;
}
