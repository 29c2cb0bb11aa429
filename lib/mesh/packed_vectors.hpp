// SPDX-License-Identifier: MIT
// Exact vectors kept packed (dyadic_points.hpp, or integers over one common
// denominator: scaled_points.hpp) and made into Vec3s only when
// a caller first asks for them: a sum's vertex positions (Mesh) and facet normals
// (FacetPlanes).
//
// Why: a sum's output has hundreds of thousands of exact coordinates; as
// Vec3s they would be most of its heap and of the time to build and destroy it,
// yet a program that sums and writes the result needs no mpq_class of them.
// The Vec3s are made on the first call of vectors(), once, by whichever
// thread asks first (std::call_once); the packed values stay, so later calls
// give the same references. Immutable otherwise: copies of a mesh or of a
// polyhedron's planes share it.
#pragma once

#include <mutex>
#include <vector>

#include "cvms/vec.hpp"
#include "dyadic_points.hpp"
#include "scaled_points.hpp"

namespace cvms::detail {

class PackedVectors {
 public:
  explicit PackedVectors(DyadicPoints vectors) noexcept : packed_(std::move(vectors)) {}
  /// Vectors kept as integers over one common denominator.
  explicit PackedVectors(ScaledPoints vectors) noexcept : scaled_(std::move(vectors)), is_scaled_(true) {}
  PackedVectors(const PackedVectors&) = delete;
  PackedVectors& operator=(const PackedVectors&) = delete;

  /// The number of vectors, in either form.
  [[nodiscard]] std::size_t size() const noexcept { return is_scaled_ ? scaled_.size() : packed_.size(); }
  /// Whether the vectors are kept as ScaledPoints (then packed() is empty).
  [[nodiscard]] bool is_scaled() const noexcept { return is_scaled_; }
  [[nodiscard]] const DyadicPoints& packed() const noexcept { return packed_; }
  /// For the builder that sized the points, before any reader sees them.
  [[nodiscard]] DyadicPoints& packed_for_writing() noexcept { return packed_; }
  /// The scaled form, as packed() and packed_for_writing().
  [[nodiscard]] const ScaledPoints& scaled() const noexcept { return scaled_; }
  [[nodiscard]] ScaledPoints& scaled_for_writing() noexcept { return scaled_; }
  /// The positions as Vec3s, made on the first call.
  /// \throw std::bad_alloc then, if memory runs out (a later call tries again).
  /// Their numerators, and their denominators past one limb, are views of
  /// limbs kept here, as an arena-built polyhedron's values are
  /// (limb_arena.hpp); a one-limb denominator is a view of a constant
  /// (LimbArena::give_back_denominator), so that making them costs no heap
  /// block per number.
  [[nodiscard]] const std::vector<Vec3>& vectors() const {
    std::call_once(made_, [this] { make_vectors(); });
    return vectors_;
  }

 private:
  void make_vectors() const;

  DyadicPoints packed_;
  ScaledPoints scaled_;
  bool is_scaled_ = false;
  mutable std::once_flag made_;
  // Declared before the values so that it outlives them.
  mutable LimbArena made_limbs_;
  mutable std::vector<Vec3> vectors_;
};

}  // namespace cvms::detail
