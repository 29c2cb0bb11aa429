// SPDX-License-Identifier: MIT
// The bodies of the libFuzzer harnesses in test/fuzz/, kept here so that the
// default (gcc) test suite can replay the committed corpora and the
// regression inputs through exactly the same code (test/fuzz_corpus_test.cpp).
//
// Each target takes arbitrary bytes. Error (any category) thrown by the
// library is the expected way to reject an input and is swallowed. A broken
// invariant or a disagreement between algorithms throws FuzzFinding; any other
// exception, a crash or a sanitizer report is a finding too (the harness lets
// it escape, libFuzzer reports it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms::fuzz {

/// An invariant the library promises was broken (or two algorithms disagree).
class FuzzFinding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// The tight limits the reader targets use: 10^5 elements, 1 MiB, 4096-char numbers.
ReadLimits fuzz_limits();

/// Readers: read, check the soup's invariants, and check that writing the soup
/// and reading it back gives the same soup (exact formats only).
void read_off_target(std::span<const std::uint8_t> data);
void read_obj_target(std::span<const std::uint8_t> data);
void read_stl_target(std::span<const std::uint8_t> data);
/// PLY: the binary round trip (doubles) when every coordinate is a double,
/// the ASCII one when the exact writer accepts the soup.
void read_ply_target(std::span<const std::uint8_t> data);
void read_points_target(std::span<const std::uint8_t> data);

/// ConvexPolyhedron::from_soup on a soup decoded from the bytes (either raw
/// faces over small rational points, or a triangulated hull with mutations).
/// Whenever from_soup accepts, the result must be convex (is_convex) and equal
/// to the exact convex hull of the soup's points, and the globally reversed
/// soup must give the same polyhedron; an unmutated triangulated hull must be
/// accepted.
void from_soup_target(std::span<const std::uint8_t> data);

/// Differential: two small point clouds -> hulls -> minkowski_sum with CVMS,
/// CHMS (and ESSDMS once implemented) and CVMS with the operands swapped must
/// give identical polyhedra (vertex sets and facets: normal, offset, vertices).
void minkowski_target(std::span<const std::uint8_t> data);

/// Convex sets of every dimension: two small sets decoded from the bytes
/// (grid points, optionally flattened onto a plane, a line or a point);
/// minkowski_sum of the two with every algorithm, in both orders, must be
/// exactly the hull of the pairwise vertex sums (support/set_oracle.hpp).
void sets_target(std::span<const std::uint8_t> data);

/// The half-space readers (fuzz_halfspace_targets.cpp): the first byte picks
/// cdd's H-representation, the plain form or cdd's V-representation
/// (mode % 3), the rest is the text. An accepted system has canonical
/// entries within the limits, survives write_halfspaces and reading back
/// exactly, and, when small, is intersected and checked as in
/// halfspaces_target; accepted points, hulled, survive write_cdd_points and
/// reading back.
void read_halfspaces_target(std::span<const std::uint8_t> data);

/// A small system decoded from the bytes (an optional bounding box, then
/// rows: new ones on a grid or of small fractions, earlier ones scaled,
/// opposed (implied equalities, thin slabs, empty sets), moved by tiny
/// steps, zero rows; optionally an equality and an extreme scale), and a
/// small convex set B. intersect_halfspaces must match the brute-force
/// triple enumeration (or name a valid direction of unboundedness, which
/// from_halfspaces must refuse), to_halfspaces must give primitive rows that
/// give the set back, and pontryagin_difference(set, B) must match the
/// brute-force intersection of the set's translates with (A ⊖ B) ⊕ B ⊆ A.
void halfspaces_target(std::span<const std::uint8_t> data);

/// The pieces reader (fuzz_solid_targets.cpp): OBJ text within
/// fuzz_limits(). Every accepted piece is convex with positive volume, and
/// write_pieces then read_pieces gives the same pieces (vertex sets).
void read_pieces_target(std::span<const std::uint8_t> data);

/// OFF text validated as a solid (Solid::from_soup). An accepted solid has
/// positive volume and is convex exactly when it has one shell and no
/// reflex edge; when small, its convex pieces' volumes (divergence theorem)
/// sum to its volume.
void read_solid_target(std::span<const std::uint8_t> data);

/// A sum of solids as one solid (minkowski_sum of two Solids): bytes
/// decoded to a polycube A (cubes of a 3 x 3 x 2 grid) and a box or a
/// polycube B (2 x 2 x 2), on one or two threads; inputs that are no valid
/// solid are skipped. The result's volume, vertex set and facet count equal
/// the exact voxel oracle's (test/support/voxel_oracle.hpp).
void solid_sum_target(std::span<const std::uint8_t> data);

/// A target by name ("read_off", "read_obj", "read_stl", "read_ply",
/// "read_points", "from_soup", "minkowski", "sets", "read_halfspaces",
/// "halfspaces", "read_pieces", "read_solid", "solid_sum"); nullptr for an
/// unknown name.
using Target = void (*)(std::span<const std::uint8_t>);
Target target_by_name(const std::string& name);
/// All target names, in a fixed order.
std::vector<std::string> target_names();

/// The decoders, exposed for regression tests that want to state an input as
/// points rather than bytes. decode_cloud reads up to max_points points of
/// three coordinates, one byte each (see fuzz_targets.cpp for the mapping).
Rational decode_coordinate(std::uint8_t byte);

}  // namespace cvms::fuzz
