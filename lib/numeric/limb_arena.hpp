// SPDX-License-Identifier: MIT
// Compact exact storage: the limbs of many exact numbers in a few
// large blocks (the numerators of rationals, their denominators longer than
// one limb, and integers), so that an output polyhedron's hundreds of
// thousands of exact numbers cost one heap block each instead of two or more,
// and destroying the polyhedron frees half as many blocks.
//
// The numbers stay mpq_class and mpz_class objects (so every `const Vec3&`
// accessor and every predicate reads them as before); only where their limbs
// live changes. Why that is sound: since GMP 6.2 every variable starts out lazily,
// with _mp_alloc == 0 and _mp_d pointing at a limb GMP does not own, and
// mpz_clear/mpq_clear free only what _mp_alloc says they own. mpz_roinit_n
// makes exactly such a variable over limbs of ours. A stored numerator is
// therefore destroyed like a fresh variable (nothing is freed) and read like
// any other; the arena must outlive every read, and a stored value must
// never be an output of a GMP function again (GMP would replace its limbs by
// fresh ones without copying them; an in-place operation would read
// garbage). Its owners enforce both: ConvexPolyhedron keeps the arena beside
// the values and exposes them only as const; the half-space intersection's
// working structs (HomogeneousDual, FacePoles, DualVertices) declare their
// arena first and are only read once built, every new value worked out in
// scratch integers and stored.
//
// A one-limb denominator stays in the limb mpq_init gave it (enough for 1
// and for every power of two below 2^64, i.e. almost all of them; a longer
// one, which would reallocate that limb, comes here too): freeing that limb
// to move the denominator here as well is slower (by about half on
// Sphere6 + rotated Sphere6 with glibc's default malloc policy): the result
// then consists of a few large blocks only, which glibc gives back to the
// kernel when the result is destroyed (heap trimming), and the next sum
// faults them in again, page by page.
//
// A builder may instead give a fresh rational's denominator limb back at once
// (give_back_denominator): the denominator becomes a view of a constant table
// of 2^0 ... 2^63 and stays one as long as only powers of two below 2^64 are
// stored into it, so that constructing a whole array reuses one heap block.
// The planes a polyhedron makes from its own corners (a loaded, transformed
// or hulled one: planes_from_first_corners) do this on whichever thread
// makes them: they are made once per polyhedron rather than once per sum,
// and a loaded Sphere6's 82,000 denominators are then neither allocated nor
// freed with it; so do a sum's packed vertices and normals when a caller
// first asks for them as Vec3s (packed_vectors.hpp). A sum's own output
// makes no rational at all: it packs its vertices and normals
// (dyadic_points.hpp).
//
// Older GMPs free unconditionally, so there store() copies into the value's
// own heap limbs instead (same values, no saving).
#pragma once

#include <gmp.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "huge_page_blocks.hpp"

namespace cvms::detail {

/// out = (negative ? -m : m) / 2^exponent in out's own limbs, m the integer
/// whose `size` limbs (least significant first; high zero limbs allowed)
/// are at `magnitude`: what LimbArena::store_dyadic writes when the arena
/// cannot hold limbs, and what the gcd-free arithmetic (dyadic.hpp) writes
/// into values that are not stored. \pre in lowest terms.
void assign_dyadic(Rational& out, const std::uint64_t* magnitude, std::size_t size, bool negative,
                   mp_bitcnt_t exponent);

class LimbArena {
 public:
  LimbArena() = default;
  /// Moves leave `other` empty (it may store again, into blocks of its own).
  LimbArena(LimbArena&& other) noexcept;
  LimbArena& operator=(LimbArena&& other) noexcept;
  LimbArena(const LimbArena&) = delete;
  LimbArena& operator=(const LimbArena&) = delete;
  ~LimbArena() = default;

  /// Whether stored values point into the arena rather than owning heap
  /// limbs: GMP >= 6.2, both in the headers compiled against and in the
  /// library loaded at run time (both install as libgmp.so.10, and a 6.1
  /// library would free the arena's limbs one by one).
  [[nodiscard]] static bool holds_limbs() noexcept;

  /// out = value, with out's numerator here. A one-limb denominator is
  /// written into out's own denominator (its mpq_init limb, kept; should
  /// that be a view, GMP allocates a limb for it, except that a denominator
  /// given back stays a view for a power of two), a longer one comes here
  /// and out's own denominator limbs are freed; so are its numerator's.
  /// \pre out does not alias value. Afterwards out is never the output of
  ///   a GMP operation (storing into it again is fine): it may be read,
  ///   copied from and destroyed, but read only while this arena lives.
  void store(Rational& out, const Rational& value);
  /// out = numerator / denominator, a fraction in lowest terms with a
  /// positive denominator, made from integers the caller computed (no
  /// rational in between): the numerator's limbs here; the denominator's in
  /// out's own limb when one limb holds it, else here as well.
  /// \pre as for store(); neither integer aliases out's.
  void store(Rational& out, mpz_srcptr numerator, mpz_srcptr denominator);
  /// out = value, its limbs here: a view of a copy, read-only as above
  /// (out's own limbs are freed; storing into it again is fine).
  void store(mpz_class& out, mpz_srcptr value);
  /// store() per coordinate.
  void store(Vec3& out, const Vec3& value);
  /// out = the integer -+(high 2^64 + low), stored like store() stores it,
  /// without a GMP value to copy from.
  void store_integer(Rational& out, std::uint64_t low, std::uint64_t high, bool negative);

  /// out = (negative ? -m : m) / 2^exponent for the integer m whose `size`
  /// limbs (least significant first; high zero limbs allowed) are at
  /// `magnitude`, stored like store() stores it: without a GMP value to copy
  /// from or a gcd to take.
  /// \pre the fraction is in lowest terms (m is odd or exponent is 0).
  void store_dyadic(Rational& out, const std::uint64_t* magnitude, std::size_t size, bool negative,
                    mp_bitcnt_t exponent);

  /// For a rational just constructed (0, its denominator 1 in the limb
  /// mpq_init allocated): frees that limb and makes the denominator a view
  /// of a constant 1. As long as only powers of two below 2^64 are stored
  /// into it, the denominator stays a view (of a constant table) rather
  /// than writing an own limb. Constructing and giving back in turn reuses
  /// one heap block for a whole array of values. From then on the value is
  /// like a stored one: it may be stored into, read, copied and destroyed,
  /// never the output of a GMP operation (an in-place one would read a
  /// denominator GMP reallocates without copying). No-op where stored
  /// values own their limbs (holds_limbs()) or on a value that is not a
  /// fresh 0.
  static void give_back_denominator(Rational& fresh) noexcept;

  /// out = -out. A view (a value an arena stored) is made anew over the
  /// same limbs with the other sign, so nothing is written to them and
  /// nothing is stored; a value that owns its limbs is negated in place.
  void negate_stored(Rational& out) const;

  /// A copy of the n limbs at source, kept here (for packed values that
  /// hold the address of their limbs, dyadic_points.hpp).
  [[nodiscard]] const mp_limb_t* copy_limbs(const mp_limb_t* source, std::size_t n);

  /// Takes over other's blocks (their addresses do not change), so that the
  /// values stored in either stay valid as long as this arena lives.
  void absorb(LimbArena&& other);

  /// Bytes of the blocks held (for tests and measurements).
  [[nodiscard]] std::size_t capacity_bytes() const noexcept { return capacity_limbs_ * sizeof(mp_limb_t); }

 private:
  [[nodiscard]] mp_limb_t* allocate(std::size_t limbs);

  std::vector<HugePageArray<mp_limb_t, BlockLife::kept>> blocks_;  // the large ones on huge pages
  mp_limb_t* free_ = nullptr;                                      ///< the unused tail of the newest block
  std::size_t free_limbs_ = 0;
  static constexpr std::size_t first_block_limbs = 512;
  std::size_t next_block_limbs_ = first_block_limbs;
  std::size_t capacity_limbs_ = 0;
};

}  // namespace cvms::detail
