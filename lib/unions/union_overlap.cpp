// SPDX-License-Identifier: MIT
// Point containment and intersection tests of a union: a union contains a
// point (meets a set) iff one of its pieces does, and a piece whose box is
// disjoint from the point's (the set's) box cannot, so only the pieces the
// box hierarchy returns are tested exactly: containment by the piece's facet
// planes (side_of_plane, exact), intersection by the library's exact GJK
// (cvms/proximity.hpp). The first piece that answers yes ends the query.
#include <string>

#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "cvms/proximity.hpp"
#include "pair_tests.hpp"
#include "union_impl.hpp"

namespace cvms {
namespace {

// A convex polyhedron is the intersection of its facets' closed half-spaces.
bool piece_contains(const ConvexPolyhedron& piece, const Vec3& p) {
  for (FaceId f : piece.mesh().faces()) {
    if (side_of_plane(p, piece.normal(f), piece.plane_offset(f)) == Sign::positive) return false;
  }
  return true;
}

[[noreturn]] void empty_operand(const char* query, const char* what) {
  throw Error(ErrorCategory::invalid_argument,
              std::string("ConvexUnion::") + query + ": the " + what + " is empty");
}

// True iff test(piece) holds for one of the pieces whose boxes overlap `box`.
template <class Test>
bool any_candidate(const ConvexUnion& u, const unions::BoxHierarchy& hierarchy, const unions::OutwardBox& box,
                   const Test& test) {
  return hierarchy.for_each_overlapping(box, [&](std::size_t i) {
    ++unions::exact_piece_tests();
    return test(u.pieces()[i]);
  });
}

}  // namespace

bool ConvexUnion::contains(const Vec3& p) const {
  if (!impl_) return false;
  return any_candidate(*this, impl_->hierarchy(), unions::point_box(p),
                       [&](const ConvexPolyhedron& piece) { return piece_contains(piece, p); });
}

bool ConvexUnion::intersects(const ConvexPolyhedron& other) const {
  if (other.num_vertices() == 0) empty_operand("intersects", "polyhedron");
  if (!impl_) return false;
  return any_candidate(*this, impl_->hierarchy(), unions::polyhedron_box(other),
                       [&](const ConvexPolyhedron& piece) { return cvms::intersects(piece, other); });
}

bool ConvexUnion::intersects(const PlacedPolyhedron& other) const {
  if (other.polyhedron().num_vertices() == 0) empty_operand("intersects", "placed polyhedron");
  if (!impl_) return false;
  return any_candidate(
      *this, impl_->hierarchy(), unions::placed_box(other),
      [&](const ConvexPolyhedron& piece) { return cvms::intersects(PlacedPolyhedron(piece), other); });
}

bool ConvexUnion::intersects(const ConvexSet& other) const {
  if (other.empty()) empty_operand("intersects", "convex set");
  if (other.dimension() == 3) return intersects(other.polyhedron());
  if (!impl_) return false;
  return any_candidate(*this, impl_->hierarchy(), unions::set_box(other), [&](const ConvexPolyhedron& piece) {
    return cvms::intersects(ConvexSet(piece), other);
  });
}

bool ConvexUnion::intersects(const ConvexUnion& other) const {
  if (!impl_ || !other.impl_) return false;
  const auto& pieces = impl_->pieces;
  const auto& other_pieces = other.impl_->pieces;
  return impl_->hierarchy().for_each_overlapping_pair(other.impl_->hierarchy(),
                                                      [&](std::size_t i, std::size_t j) {
                                                        ++unions::exact_piece_tests();
                                                        return cvms::intersects(pieces[i], other_pieces[j]);
                                                      });
}

}  // namespace cvms
