// SPDX-License-Identifier: MIT
// A mesh's exact positions kept packed (dyadic_points.hpp) and made into
// Vec3s only when a caller first asks for them (issue 14: "mpq_class made
// only when a caller asks for one").
//
// Why: a sum's output has hundreds of thousands of coordinates; as Vec3s
// they were most of its heap and of the time to build and destroy it, yet a
// program that sums, writes the result or sums it again needs no mpq_class
// of them (the library's own readers take the packed values). Mesh::position
// and Mesh::positions make them on first call, once, by whichever thread
// asks first (std::call_once); the packed values stay, so equal calls give
// the same references. Immutable otherwise: copies of a mesh share it.
#pragma once

#include <mutex>
#include <vector>

#include "cvms/vec.hpp"
#include "dyadic_points.hpp"

namespace cvms::detail {

class LazyPositions {
 public:
  explicit LazyPositions(DyadicPoints points) noexcept : packed_(std::move(points)) {}
  LazyPositions(const LazyPositions&) = delete;
  LazyPositions& operator=(const LazyPositions&) = delete;

  [[nodiscard]] const DyadicPoints& packed() const noexcept { return packed_; }
  /// For the builder that sized the points, before any reader sees them.
  [[nodiscard]] DyadicPoints& packed_for_writing() noexcept { return packed_; }
  /// The positions as Vec3s, made on the first call.
  /// \throw std::bad_alloc then, if memory runs out (a later call tries again).
  /// Their numerators are views of limbs these positions keep, as an
  /// arena-built polyhedron's values are (limb_arena.hpp).
  [[nodiscard]] const std::vector<Vec3>& vectors() const {
    std::call_once(made_, [this] { make_vectors(); });
    return vectors_;
  }

 private:
  void make_vectors() const;

  DyadicPoints packed_;
  mutable std::once_flag made_;
  // Declared before the values so that it outlives them.
  mutable LimbArena made_limbs_;
  mutable std::vector<Vec3> vectors_;
};

}  // namespace cvms::detail
