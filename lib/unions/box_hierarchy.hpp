// SPDX-License-Identifier: MIT
// A bounding-volume hierarchy over the pieces of a union: a binary tree of
// outward-rounded boxes (outward_box.hpp), one piece per leaf, built top down
// by splitting the pieces at the median of their box centres along the
// widest axis of those centres. A parent's box is the merge of its
// children's, so it contains them exactly (min and max of doubles are
// exact), and a subtree's box contains every piece below it: a query that
// skips a subtree on its box skips only pieces it could not have used.
//
// The queries here only enumerate candidates; the exact tests are the
// callers':
//  - for_each_overlapping: the leaves whose boxes overlap a query box;
//  - for_each_overlapping_pair: the leaf pairs of two hierarchies whose boxes
//    overlap;
//  - nearest_first / nearest_pairs_first: branch and bound. Subtrees (or
//    subtree pairs) wait in a priority queue by the lower bound of their box
//    distance; the smallest is expanded next, and the search ends when the
//    smallest bound exceeds the caller's best exact value. Every leaf (pair)
//    whose box bound is at most the best value is still visited, so a caller
//    that keeps the first of tied answers sees them all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "outward_box.hpp"

namespace cvms::unions {

class BoxHierarchy {
 public:
  /// A hierarchy over these boxes (piece i has boxes[i]); empty for none.
  explicit BoxHierarchy(std::span<const OutwardBox> boxes);

  [[nodiscard]] bool empty() const noexcept { return nodes_.empty(); }

  /// Calls visit(piece) for each piece whose box overlaps `query`; stops
  /// and returns true as soon as visit returns true.
  bool for_each_overlapping(const OutwardBox& query, const std::function<bool(std::size_t)>& visit) const;

  /// Calls visit(piece, other_piece) for each pair whose boxes overlap;
  /// stops and returns true as soon as visit returns true.
  bool for_each_overlapping_pair(const BoxHierarchy& other,
                                 const std::function<bool(std::size_t, std::size_t)>& visit) const;

  /// Branch and bound against one box: visit(piece) for the pieces in order
  /// of their boxes' lower distance bound, until that bound exceeds
  /// bound_limit() (a double >= the caller's best exact value, re-read after
  /// each visit).
  void nearest_first(const OutwardBox& query, const std::function<void(std::size_t)>& visit,
                     const std::function<double()>& bound_limit) const;

  /// The same over pairs of pieces of two hierarchies.
  void nearest_pairs_first(const BoxHierarchy& other,
                           const std::function<void(std::size_t, std::size_t)>& visit,
                           const std::function<double()>& bound_limit) const;

 private:
  static constexpr std::uint32_t no_piece = 0xffffffffU;
  struct Node {
    OutwardBox box;
    std::uint32_t left = 0;  // children, when piece == no_piece
    std::uint32_t right = 0;
    std::uint32_t piece = no_piece;
  };

  std::uint32_t build(std::span<const OutwardBox> boxes, std::span<std::uint32_t> pieces);
  [[nodiscard]] bool is_leaf(std::uint32_t node) const { return nodes_[node].piece != no_piece; }

  std::vector<Node> nodes_;  // the root is the last node built
  std::uint32_t root_ = 0;
};

}  // namespace cvms::unions
