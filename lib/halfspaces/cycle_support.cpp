// SPDX-License-Identifier: MIT
// The climb of cycle_support.hpp. It moves only to a strictly higher
// neighbour, so it ends; where it ends both neighbours are not higher (the
// one it came from is lower), so the vertex is a maximiser.
#include "cycle_support.hpp"

#include <utility>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"

namespace cvms::detail {

CycleSupport::CycleSupport(std::vector<Vec3> cycle) : cycle_(std::move(cycle)) {
  if (cycle_.empty()) throw Error(ErrorCategory::invalid_argument, "CycleSupport: no vertices");
}

bool CycleSupport::higher(std::size_t j, std::size_t i, const Vec3& u) const {
  return compare_dot(cycle_[j], cycle_[i], u) == Sign::positive;
}

std::size_t CycleSupport::maximiser(const Vec3& u) {
  std::size_t i = last_;
  // Forward when the next vertex is higher, otherwise backward: from a
  // vertex that is not a maximiser some direction climbs (both do from the
  // minimum), and a climb in either one ends at a maximiser.
  const bool forward = higher(next(i), i, u);
  if (forward) {
    i = next(i);
    ++steps_;
  }
  for (std::size_t j = forward ? next(i) : prev(i); higher(j, i, u); j = forward ? next(i) : prev(i)) {
    i = j;
    ++steps_;
  }
  last_ = i;
  return i;
}

}  // namespace cvms::detail
