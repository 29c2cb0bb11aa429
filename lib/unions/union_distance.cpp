// SPDX-License-Identifier: MIT
// The distance from a union to a set (or to another union) by branch and
// bound. dist(U, B) = min over pieces Ai of dist(Ai, B), since a closest
// pair of points lies in some piece (the pieces are closed and finitely
// many); for two unions the minimum runs over piece pairs. The box
// hierarchy hands out pieces (pairs) in increasing order of a lower bound of
// their box distance (outward_box.hpp), which is at most the distance of the
// pieces themselves; once that bound exceeds the best exact squared distance
// found, no remaining piece can do better and the search ends. Each
// candidate's distance is the library's exact GJK (cvms/proximity.hpp).
//
// Ties: the answer is the first pair, in (piece, other_piece) order, at the
// minimum distance. The search ends only on a bound strictly above the best
// value, so every pair that could tie is still visited, and the answer does
// not depend on the hierarchy's shape or the visiting order.
#include <limits>
#include <string>

#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "pair_tests.hpp"
#include "union_impl.hpp"

namespace cvms {
namespace {

// The best answer so far and a double >= its squared distance, the bound
// that ends the search.
class Nearest {
 public:
  void offer(DistanceResult d, std::size_t piece, std::size_t other_piece) {
    ++unions::exact_piece_tests();
    if (found_) {
      const int order = cmp(d.squared_distance, best_.distance.squared_distance);
      if (order > 0) return;
      if (order == 0 && std::pair(piece, other_piece) > std::pair(best_.piece, best_.other_piece)) return;
    }
    found_ = true;
    limit_ = unions::round_up(d.squared_distance);
    best_ = UnionDistance{std::move(d), piece, other_piece};
  }
  [[nodiscard]] double limit() const { return limit_; }
  UnionDistance take() { return std::move(best_); }

 private:
  bool found_ = false;
  double limit_ = std::numeric_limits<double>::infinity();
  UnionDistance best_;
};

[[noreturn]] void empty_operand(const char* what) {
  throw Error(ErrorCategory::invalid_argument,
              std::string("ConvexUnion::squared_distance: the ") + what + " is empty");
}

}  // namespace

UnionDistance ConvexUnion::squared_distance(const ConvexPolyhedron& other) const {
  if (empty()) empty_operand("union");
  if (other.num_vertices() == 0) empty_operand("polyhedron");
  const auto& pieces = impl_->pieces;
  Nearest nearest;
  impl_->hierarchy().nearest_first(
      unions::polyhedron_box(other),
      [&](std::size_t i) { nearest.offer(cvms::squared_distance(pieces[i], other), i, 0); },
      [&] { return nearest.limit(); });
  return nearest.take();
}

UnionDistance ConvexUnion::squared_distance(const ConvexSet& other) const {
  if (empty()) empty_operand("union");
  if (other.empty()) empty_operand("convex set");
  if (other.dimension() == 3) return squared_distance(other.polyhedron());
  const auto& pieces = impl_->pieces;
  Nearest nearest;
  impl_->hierarchy().nearest_first(
      unions::set_box(other),
      [&](std::size_t i) { nearest.offer(cvms::squared_distance(ConvexSet(pieces[i]), other), i, 0); },
      [&] { return nearest.limit(); });
  return nearest.take();
}

UnionDistance ConvexUnion::squared_distance(const ConvexUnion& other) const {
  if (empty()) empty_operand("union");
  if (other.empty()) empty_operand("other union");
  const auto& pieces = impl_->pieces;
  const auto& other_pieces = other.impl_->pieces;
  Nearest nearest;
  impl_->hierarchy().nearest_pairs_first(
      other.impl_->hierarchy(),
      [&](std::size_t i, std::size_t j) {
        nearest.offer(cvms::squared_distance(pieces[i], other_pieces[j]), i, j);
      },
      [&] { return nearest.limit(); });
  return nearest.take();
}

}  // namespace cvms
