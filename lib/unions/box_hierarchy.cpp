// SPDX-License-Identifier: MIT
// The box hierarchy's construction and traversals (box_hierarchy.hpp).
#include "box_hierarchy.hpp"

#include <algorithm>
#include <limits>
#include <queue>
#include <string>
#include <tuple>
#include <utility>

#include "cvms/error.hpp"

namespace cvms::unions {
namespace {

// Twice the box's centre along axis i: only compared, so the halving is
// left out. Infinite bounds give an infinite or NaN centre, which only makes
// the split uneven; nth_element is given a strict weak order in any case.
double centre2(const OutwardBox& box, std::size_t i) {
  const double c = box.lo[i] + box.hi[i];
  return c == c ? c : 0.0;
}

double extent(const OutwardBox& box) {
  double sum = 0.0;
  for (std::size_t i = 0; i < 3; ++i) sum += box.hi[i] - box.lo[i];
  return sum;
}

}  // namespace

BoxHierarchy::BoxHierarchy(std::span<const OutwardBox> boxes) {
  if (boxes.empty()) return;
  if (boxes.size() >= (std::size_t{1} << 31)) {
    throw Error(ErrorCategory::limit, "ConvexUnion: " + std::to_string(boxes.size()) +
                                          " pieces, beyond the 2^31 - 1 a union indexes");
  }
  std::vector<std::uint32_t> pieces(boxes.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) pieces[i] = static_cast<std::uint32_t>(i);
  nodes_.reserve(2 * boxes.size() - 1);
  root_ = build(boxes, pieces);
}

std::uint32_t BoxHierarchy::build(std::span<const OutwardBox> boxes, std::span<std::uint32_t> pieces) {
  Node node;
  if (pieces.size() == 1) {
    node.box = boxes[pieces[0]];
    node.piece = pieces[0];
  } else {
    // The widest axis of the centres, then the median along it.
    std::size_t axis = 0;
    double widest = -1.0;
    for (std::size_t i = 0; i < 3; ++i) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (std::uint32_t p : pieces) {
        lo = std::min(lo, centre2(boxes[p], i));
        hi = std::max(hi, centre2(boxes[p], i));
      }
      if (hi - lo > widest) {
        widest = hi - lo;
        axis = i;
      }
    }
    const std::size_t half = pieces.size() / 2;
    std::nth_element(pieces.begin(), pieces.begin() + static_cast<std::ptrdiff_t>(half), pieces.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return std::pair(centre2(boxes[a], axis), a) < std::pair(centre2(boxes[b], axis), b);
                     });
    node.left = build(boxes, pieces.first(half));
    node.right = build(boxes, pieces.subspan(half));
    node.box = merged(nodes_[node.left].box, nodes_[node.right].box);
  }
  nodes_.push_back(node);
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

bool BoxHierarchy::for_each_overlapping(const OutwardBox& query,
                                        const std::function<bool(std::size_t)>& visit) const {
  if (empty()) return false;
  std::vector<std::uint32_t> stack{root_};
  while (!stack.empty()) {
    const std::uint32_t n = stack.back();
    stack.pop_back();
    if (!overlaps(nodes_[n].box, query)) continue;
    if (is_leaf(n)) {
      if (visit(nodes_[n].piece)) return true;
      continue;
    }
    stack.push_back(nodes_[n].right);
    stack.push_back(nodes_[n].left);
  }
  return false;
}

bool BoxHierarchy::for_each_overlapping_pair(
    const BoxHierarchy& other, const std::function<bool(std::size_t, std::size_t)>& visit) const {
  if (empty() || other.empty()) return false;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{root_, other.root_}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];
    if (!overlaps(na.box, nb.box)) continue;
    const bool leaf_a = is_leaf(a), leaf_b = other.is_leaf(b);
    if (leaf_a && leaf_b) {
      if (visit(na.piece, nb.piece)) return true;
    } else if (!leaf_a && (leaf_b || extent(na.box) >= extent(nb.box))) {
      stack.emplace_back(na.right, b);
      stack.emplace_back(na.left, b);
    } else {
      stack.emplace_back(a, nb.right);
      stack.emplace_back(a, nb.left);
    }
  }
  return false;
}

void BoxHierarchy::nearest_first(const OutwardBox& query, const std::function<void(std::size_t)>& visit,
                                 const std::function<double()>& bound_limit) const {
  if (empty()) return;
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  queue.emplace(lower_squared_distance(nodes_[root_].box, query), root_);
  while (!queue.empty()) {
    const auto [bound, n] = queue.top();
    queue.pop();
    if (bound > bound_limit()) return;  // every other entry's bound is at least as large
    if (is_leaf(n)) {
      visit(nodes_[n].piece);
      continue;
    }
    for (std::uint32_t child : {nodes_[n].left, nodes_[n].right}) {
      queue.emplace(lower_squared_distance(nodes_[child].box, query), child);
    }
  }
}

void BoxHierarchy::nearest_pairs_first(const BoxHierarchy& other,
                                       const std::function<void(std::size_t, std::size_t)>& visit,
                                       const std::function<double()>& bound_limit) const {
  if (empty() || other.empty()) return;
  using Entry = std::tuple<double, std::uint32_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  auto push = [&](std::uint32_t a, std::uint32_t b) {
    queue.emplace(lower_squared_distance(nodes_[a].box, other.nodes_[b].box), a, b);
  };
  push(root_, other.root_);
  while (!queue.empty()) {
    const auto [bound, a, b] = queue.top();
    queue.pop();
    if (bound > bound_limit()) return;
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];
    const bool leaf_a = is_leaf(a), leaf_b = other.is_leaf(b);
    if (leaf_a && leaf_b) {
      visit(na.piece, nb.piece);
    } else if (!leaf_a && (leaf_b || extent(na.box) >= extent(nb.box))) {
      push(na.left, b);
      push(na.right, b);
    } else {
      push(a, nb.left);
      push(a, nb.right);
    }
  }
}

}  // namespace cvms::unions
