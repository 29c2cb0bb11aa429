// SPDX-License-Identifier: MIT
// Exact dyadic points without a GMP object per coordinate, so without one
// heap allocation per exact number.
//
// Every coordinate of a Minkowski sum of inputs read from doubles is dyadic
// (a double, or a sum of doubles: m / 2^e). Kept as mpq_class, each such
// coordinate would be a 32-byte mpq_t, a heap block for its denominator and its
// numerator's limbs in an arena (limb_arena.hpp): about 220 bytes and three
// pointer chases per point, made by GMP calls and freed one block at a
// time. Here a coordinate is 16 bytes, PackedDyadic: its numerator inline
// when it fits one limb (almost always: sums of doubles of close
// exponents), else the address of its limbs in an arena the points keep,
// and the exponent of its denominator. Building one is a few stores;
// destroying the points frees a few large blocks.
//
// A value is packed in lowest terms (odd numerator or exponent 0; zero is
// size 0, exponent 0), so equal values have equal packings and the mpq_class
// made from one is canonical without a gcd.
#pragma once

#include <gmp.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "dyadic.hpp"
#include "huge_page_blocks.hpp"
#include "limb_arena.hpp"
#include "result_slab.hpp"

namespace cvms::detail {

// A packed numerator is read as GMP limbs (mpz_roinit_n) and written from
// 64-bit words (FixedDyadic): both must be the same type.
static_assert(std::is_same_v<mp_limb_t, std::uint64_t>, "GMP limbs must be 64-bit unsigned longs");

/// One exact dyadic number: (size < 0 ? -1 : 1) * |numerator| / 2^exponent.
struct PackedDyadic {
  /// The numerator's magnitude when |size| <= 1, else the address of its
  /// |size| limbs (least significant first, the last one nonzero).
  std::uint64_t word = 0;
  std::uint32_t exponent = 0;  ///< the denominator is 2^exponent
  std::int32_t size = 0;       ///< signed limb count of the numerator, as GMP's _mp_size

  /// The numerator's limbs (at least one readable limb, also for zero).
  [[nodiscard]] const mp_limb_t* limbs() const noexcept {
    return size >= -1 && size <= 1 ? &word : reinterpret_cast<const mp_limb_t*>(word);
  }
  /// A read-only GMP view of the numerator, valid while this value and the
  /// arena of its limbs live. \pre `view` is not cleared or written by GMP.
  [[nodiscard]] mpz_srcptr numerator(mpz_t view) const noexcept { return mpz_roinit_n(view, limbs(), size); }
};

/// The canonical packing of a value, its long numerators' limbs copied into
/// arena; false (out unspecified) when value is not dyadic or its
/// exponent or numerator do not fit 32 bits.
[[nodiscard]] bool pack_dyadic(const Rational& value, LimbArena& arena, PackedDyadic& out);
/// The canonical packing of value (not necessarily in lowest terms), its
/// two-limb numerator copied into arena when it does not fit one.
/// \pre value.exponent < 2^32.
void pack_dyadic(FixedDyadic<2> value, LimbArena& arena, PackedDyadic& out);
/// out = the value, canonical, in out's own limbs.
void unpack_dyadic(const PackedDyadic& value, Rational& out);

/// A fixed number of exact dyadic points, 0 until stored. Threads may store
/// into distinct points concurrently, each with an arena of its own, which
/// the points must then keep (keep_limbs) before the arena goes.
class DyadicPoints {
 public:
  DyadicPoints() = default;
  /// No points yet, their coordinates to be carved from allocator's slab.
  explicit DyadicPoints(const KeptAllocator<PackedDyadic>& allocator) : coordinates_(allocator) {}
  /// count points at the origin (coordinates carved from allocator's slab, if any).
  explicit DyadicPoints(std::size_t count, const KeptAllocator<PackedDyadic>& allocator = {})
      : coordinates_(3 * count, allocator) {}
  /// Adds to plan the room for count points (result_slab.hpp).
  static void plan(SlabPlan& plan, std::size_t count) { plan.add<PackedDyadic>(3 * count); }

  [[nodiscard]] std::size_t size() const noexcept { return coordinates_.size() / 3; }
  /// Room for count points without reallocating.
  void reserve(std::size_t count) { coordinates_.reserve(3 * count); }
  /// A new point at the origin after the others; its index.
  std::size_t append() {
    coordinates_.resize(coordinates_.size() + 3);
    return size() - 1;
  }
  /// Coordinate `axis` (0, 1, 2 for x, y, z) of point j.
  [[nodiscard]] const PackedDyadic& coordinate(std::size_t j, int axis) const noexcept {
    return coordinates_[3 * j + static_cast<std::size_t>(axis)];
  }
  [[nodiscard]] PackedDyadic& coordinate(std::size_t j, int axis) noexcept {
    return coordinates_[3 * j + static_cast<std::size_t>(axis)];
  }
  /// Packs v as point j, long numerators' limbs in arena; false (point j
  /// unspecified) when a coordinate does not pack (pack_dyadic).
  [[nodiscard]] bool pack(std::size_t j, const Vec3& v, LimbArena& arena) {
    return pack_dyadic(v.x, arena, coordinate(j, 0)) && pack_dyadic(v.y, arena, coordinate(j, 1)) &&
           pack_dyadic(v.z, arena, coordinate(j, 2));
  }
  /// Point j as exact rationals (each owning its limbs).
  [[nodiscard]] Vec3 point(std::size_t j) const;
  /// Every point as exact rationals, in order.
  [[nodiscard]] std::vector<Vec3> to_vectors() const;

  /// Keeps arena's blocks: the limbs of long numerators packed through it
  /// stay valid as long as these points live.
  void keep_limbs(LimbArena&& arena) { limbs_.absorb(std::move(arena)); }
  /// The slab the coordinates were carved from, or null (result_slab.hpp).
  [[nodiscard]] const ResultSlab* slab() const noexcept { return coordinates_.get_allocator().slab().get(); }
  /// The arena the points keep, for a single writer.
  [[nodiscard]] LimbArena& limbs() noexcept { return limbs_; }

 private:
  // Declared first so that it outlives every coordinate pointing into it.
  LimbArena limbs_;
  KeptVector<PackedDyadic> coordinates_;  // 3 per point
};

}  // namespace cvms::detail
