// SPDX-License-Identifier: MIT
// Peer rows of cvms_solid_sum_bench (built only with CVMS_BENCH_PEERS and a
// found CGAL): CGAL's exact Nef minkowski_sum_3 on the same solids as the
// exact rows, BM_CgalNef/<pair>/1. Nef sums take seconds to minutes where
// cvms takes milliseconds, so its rows are off unless CVMS_BENCH_NEF is set:
// "small" adds every pair but the real mesh, "all" spot + icosphere too
// (minutes on its own). Each row runs
// once (one iteration, one repetition, whatever the command line asks).
#include <benchmark/benchmark.h>

#ifdef CVMS_BENCH_HAVE_CGAL

#include <cstdlib>
#include <exception>
#include <string_view>

#include "peer_cgal_nef.hpp"
#include "solid_sum_operands.hpp"

namespace {

using cvms_bench::PairGroup;
using cvms_bench::SolidPair;

void cgal_nef(benchmark::State& state, const SolidPair& pair, unsigned /*threads*/) {
  const cvms_bench::CgalNefOperand a(cvms_bench::solid_sum_operand(pair.a));
  const cvms_bench::CgalNefOperand b(cvms_bench::solid_sum_operand(pair.b));
  cvms_bench::CgalNefSum sum;
  try {
    for (auto _ : state) {
      sum = a.minkowski_sum(b);
      benchmark::DoNotOptimize(sum);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["peer_vertices"] = static_cast<double>(sum.vertices);
  state.counters["peer_facets"] = static_cast<double>(sum.facets);
  state.counters["peer_volumes"] = static_cast<double>(sum.volumes);
  state.counters["peer_simple"] = sum.simple ? 1 : 0;
}

std::string_view nef_cases() {
  const char* value = std::getenv("CVMS_BENCH_NEF");
  return value == nullptr ? std::string_view() : std::string_view(value);
}

bool small_nef_case(const SolidPair& pair) { return pair.group != PairGroup::mesh; }

bool every_nef_case(const SolidPair& /*pair*/) { return true; }

const bool registered = [] {
  const std::string_view cases = nef_cases();
  if (cases != "small" && cases != "all") return false;
  for (auto* row : cvms_bench::register_solid_rows("BM_CgalNef", cgal_nef,
                                                   cases == "all" ? every_nef_case : small_nef_case, false))
    row->Iterations(1)->Repetitions(1);
  return true;
}();

}  // namespace

#endif  // CVMS_BENCH_HAVE_CGAL
