// SPDX-License-Identifier: MIT
// The support function of a convex polygon (or a segment or a point) given
// by its vertex cycle, by a hill-climb along the cycle warm-started at the
// previous answer. Why a climb is correct: <x, u> along the cycle of a
// convex polygon rises to its maximum and falls to its minimum once each
// (ties only on an edge orthogonal to u, or everywhere when u is orthogonal
// to the plane), and a vertex whose two neighbours are not higher is a
// maximiser: the polygon lies in the cone at that vertex spanned by its two
// edges, on which <x − v, u> <= 0. Why warm-started: pontryagin_difference
// asks for h_B(n) over the facet normals n of A, and neighbouring normals
// have neighbouring maximisers, so a sweep of directions around the polygon
// costs O(vertices + queries) steps in all instead of a scan per query.
// Every comparison is compare_dot (cvms/predicates.hpp), exact.
#pragma once

#include <cstddef>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

class CycleSupport {
 public:
  /// `cycle`: the vertices in cyclic order (a polygon's cycle, a segment's
  /// two endpoints or one point); at least one.
  explicit CycleSupport(std::vector<Vec3> cycle);

  /// The index in the cycle of a vertex maximising <x, u>; the climb starts
  /// at the previous answer.
  std::size_t maximiser(const Vec3& u);

  /// The vertices, as given.
  [[nodiscard]] const std::vector<Vec3>& cycle() const noexcept { return cycle_; }

  /// Moves along the cycle made by all maximiser() calls so far.
  [[nodiscard]] std::size_t steps() const noexcept { return steps_; }

 private:
  [[nodiscard]] std::size_t next(std::size_t i) const noexcept { return i + 1 == cycle_.size() ? 0 : i + 1; }
  [[nodiscard]] std::size_t prev(std::size_t i) const noexcept { return i == 0 ? cycle_.size() - 1 : i - 1; }
  [[nodiscard]] bool higher(std::size_t j, std::size_t i, const Vec3& u) const;

  std::vector<Vec3> cycle_;
  std::size_t last_ = 0;
  std::size_t steps_ = 0;
};

}  // namespace cvms::detail
