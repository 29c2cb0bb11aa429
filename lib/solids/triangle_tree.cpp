// SPDX-License-Identifier: MIT
// The hierarchy of triangle_tree.hpp: its construction and its three
// searches (pairs of overlapping boxes, boxes near a point, boxes on a ray).
#include "triangle_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace cvms::detail {

double double_below(const Rational& x) {
  return std::nextafter(to_double_nearest(x), -std::numeric_limits<double>::infinity());
}
double double_above(const Rational& x) {
  return std::nextafter(to_double_nearest(x), std::numeric_limits<double>::infinity());
}

Box point_box(const Vec3& p) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    b.lo[static_cast<std::size_t>(k)] = double_below(p[k]);
    b.hi[static_cast<std::size_t>(k)] = double_above(p[k]);
  }
  return b;
}

void extend(Box& b, const Box& other) {
  for (std::size_t k = 0; k < 3; ++k) {
    b.lo[k] = std::min(b.lo[k], other.lo[k]);
    b.hi[k] = std::max(b.hi[k], other.hi[k]);
  }
}

namespace {

bool overlap(const Box& a, const Box& b) {
  for (std::size_t k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

// Exact slab test: is there s >= 0 with lo <= p + s d <= hi on every axis?
// An infinite bound (a coordinate beyond the doubles) constrains nothing.
bool ray_meets_box(const Vec3& p, const Vec3& d, const Box& box) {
  Rational enter = 0;
  Rational leave;
  bool bounded = false;
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double lo = box.lo[i];
    const double hi = box.hi[i];
    const int dir = sgn(d[k]);
    if (dir == 0) {
      if ((std::isfinite(lo) && p[k] < Rational(lo)) || (std::isfinite(hi) && p[k] > Rational(hi)))
        return false;
      continue;
    }
    // Moving along d, the ray enters the slab at the near bound and leaves it
    // at the far one.
    const double near = dir > 0 ? lo : hi;
    const double far = dir > 0 ? hi : lo;
    if (std::isfinite(near)) {
      Rational s = (Rational(near) - p[k]) / d[k];
      if (s > enter) enter = std::move(s);
    }
    if (std::isfinite(far)) {
      Rational s = (Rational(far) - p[k]) / d[k];
      if (!bounded || s < leave) {
        leave = std::move(s);
        bounded = true;
      }
    }
    if (bounded && enter > leave) return false;
  }
  return true;
}

// The ray's start and direction enclosed in doubles, once per ray, for the
// box filter below. Usable when every bound is finite and no direction
// interval holds zero (then no quotient below is NaN).
struct RayEnclosure {
  std::array<double, 3> p_lo, p_hi, d_lo, d_hi;
  bool usable = true;
};

RayEnclosure enclose(const Vec3& p, const Vec3& d) {
  RayEnclosure e;
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    e.p_lo[i] = double_below(p[k]);
    e.p_hi[i] = double_above(p[k]);
    const int dir = sgn(d[k]);
    e.d_lo[i] = dir == 0 ? 0.0 : double_below(d[k]);
    e.d_hi[i] = dir == 0 ? 0.0 : double_above(d[k]);
    const bool finite = std::isfinite(e.p_lo[i]) && std::isfinite(e.p_hi[i]) && std::isfinite(e.d_lo[i]) &&
                        std::isfinite(e.d_hi[i]);
    const bool signed_interval = dir == 0 || (dir > 0 ? e.d_lo[i] > 0 : e.d_hi[i] < 0);
    e.usable = e.usable && finite && signed_interval;
  }
  return e;
}

double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

// A lower and an upper bound on (bound - p) / d for p in [p_lo, p_hi] and
// d in [d_lo, d_hi] (zero not in it): interval arithmetic, each rounded
// result moved one step outward (round to nearest errs by at most half a
// step). For d > 0 the quotient grows with the numerator and takes its
// extremes at the divisor's far end for a nonnegative numerator and at its
// near end otherwise; d < 0 is the same after negating numerator and
// divisor.
double quotient_below(double bound, double p_lo, double p_hi, double d_lo, double d_hi) {
  if (d_hi < 0) return quotient_below(-bound, -p_hi, -p_lo, -d_hi, -d_lo);
  const double n = down(bound - p_hi);
  return down(n / (n >= 0 ? d_hi : d_lo));
}
double quotient_above(double bound, double p_lo, double p_hi, double d_lo, double d_hi) {
  if (d_hi < 0) return quotient_above(-bound, -p_hi, -p_lo, -d_hi, -d_lo);
  const double n = up(bound - p_lo);
  return up(n / (n >= 0 ? d_lo : d_hi));
}

// The slab test of ray_meets_box on the enclosures: false only when the ray
// certainly misses the box (the latest entry's lower bound exceeds the
// earliest exit's upper bound, or a slab along which the ray does not move
// certainly excludes p). A true answer may be wrong near the box's surface;
// the caller's exact test of the triangle decides those.
bool ray_may_meet_box(const RayEnclosure& e, const Box& box) {
  double enter = 0;
  double leave = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < 3; ++i) {
    const double lo = box.lo[i], hi = box.hi[i];
    if (e.d_lo[i] == 0 && e.d_hi[i] == 0) {
      if (e.p_hi[i] < lo || e.p_lo[i] > hi) return false;
      continue;
    }
    const bool forward = e.d_lo[i] > 0;
    const double near = forward ? lo : hi, far = forward ? hi : lo;
    if (std::isfinite(near)) enter = std::max(enter, quotient_below(near, e.p_lo[i], e.p_hi[i], e.d_lo[i], e.d_hi[i]));
    if (std::isfinite(far)) leave = std::min(leave, quotient_above(far, e.p_lo[i], e.p_hi[i], e.d_lo[i], e.d_hi[i]));
    if (enter > leave) return false;
  }
  return true;
}

double finite_part(double x) {
  return std::clamp(x, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
}

}  // namespace

TriangleTree::TriangleTree(std::span<const Vec3> vertices,
                           std::span<const std::array<std::uint32_t, 3>> triangles) {
  std::vector<Box> vertex_boxes;
  vertex_boxes.reserve(vertices.size());
  for (const Vec3& v : vertices) vertex_boxes.push_back(point_box(v));
  boxes_.reserve(triangles.size());
  for (const auto& t : triangles) {
    Box b = vertex_boxes[t[0]];
    extend(b, vertex_boxes[t[1]]);
    extend(b, vertex_boxes[t[2]]);
    boxes_.push_back(b);
  }
  build_all();
}

TriangleTree::TriangleTree(std::vector<Box> boxes) : boxes_(std::move(boxes)) { build_all(); }

void TriangleTree::build_all() {
  std::vector<std::array<double, 3>> centres;
  centres.reserve(boxes_.size());
  for (const Box& b : boxes_) {
    std::array<double, 3> c{};
    for (std::size_t k = 0; k < 3; ++k) c[k] = finite_part(b.lo[k]) / 2 + finite_part(b.hi[k]) / 2;
    centres.push_back(c);
  }
  order_.resize(boxes_.size());
  for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  // A binary tree whose leaves hold at least one box has fewer than 2n nodes.
  nodes_.reserve(2 * boxes_.size());
  if (!boxes_.empty()) build(0, static_cast<std::uint32_t>(boxes_.size()), centres);
}

std::uint32_t TriangleTree::build(std::uint32_t begin, std::uint32_t end,
                                  std::span<const std::array<double, 3>> centres) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  Box box = boxes_[order_[begin]];
  for (std::uint32_t i = begin + 1; i < end; ++i) extend(box, boxes_[order_[i]]);
  nodes_.push_back({box, begin, end, 0});
  constexpr std::uint32_t leaf_size = 4;
  if (end - begin <= leaf_size) return index;
  std::uint32_t mid = area_split(begin, end, centres);
  if (mid == begin) mid = median_split(begin, end, box, centres);
  build(begin, mid, centres);
  const std::uint32_t right = build(mid, end, centres);
  nodes_[index].right = right;
  return index;
}

std::uint32_t TriangleTree::median_split(std::uint32_t begin, std::uint32_t end, const Box& box,
                                         std::span<const std::array<double, 3>> centres) {
  std::size_t axis = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (box.hi[k] - box.lo[k] > box.hi[axis] - box.lo[axis]) axis = k;
  // Always the median position, even when the centres are equal: the halves
  // are then arbitrary but the depth stays logarithmic.
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  return mid;
}

namespace {

constexpr std::size_t kBins = 16;

// Half the surface area of a box: the cost weight of the split below.
double half_area(const Box& b) {
  std::array<double, 3> e{};
  for (std::size_t k = 0; k < 3; ++k) e[k] = finite_part(b.hi[k]) - finite_part(b.lo[k]);
  return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

// The bin of centre c among kBins equal bins over [lo, lo + width].
std::size_t bin_of(double c, double lo, double width) {
  const double t = (c - lo) / width * static_cast<double>(kBins);
  return std::min(kBins - 1, static_cast<std::size_t>(std::max(0.0, t)));
}

struct AreaSplit {
  double cost = std::numeric_limits<double>::infinity();
  std::size_t axis = 0, last_left_bin = 0;
  double lo = 0, width = 0;
};

}  // namespace

// The boxes' centres binned along each axis; the split between bins that
// minimises area(left) * |left| + area(right) * |right| (a ray meets a box
// with a chance about proportional to its area), each side holding at least
// an eighth of the boxes. Overlapping long boxes (a fan of thin triangles)
// then gather in one node instead of widening every node along their span.
// Returns the split position after partitioning order_, or begin if no
// split qualifies.
std::uint32_t TriangleTree::area_split(std::uint32_t begin, std::uint32_t end,
                                       std::span<const std::array<double, 3>> centres) {
  const std::uint32_t n = end - begin;
  const std::uint32_t least = std::max<std::uint32_t>(1, n / 8);
  AreaSplit best;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::uint32_t i = begin; i < end; ++i) {
      lo = std::min(lo, centres[order_[i]][axis]);
      hi = std::max(hi, centres[order_[i]][axis]);
    }
    const double width = hi - lo;
    if (!(width > 0) || !std::isfinite(width)) continue;
    std::array<std::uint32_t, kBins> count{};
    std::array<Box, kBins> bin_box{};
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::size_t b = bin_of(centres[order_[i]][axis], lo, width);
      if (count[b]++ == 0) bin_box[b] = boxes_[order_[i]];
      else extend(bin_box[b], boxes_[order_[i]]);
    }
    // Right-side areas by suffix, then the left side grown bin by bin.
    std::array<double, kBins> right_area{};
    std::array<std::uint32_t, kBins> right_count{};
    Box grown{};
    std::uint32_t seen = 0;
    for (std::size_t b = kBins; b-- > 1;) {
      if (count[b] > 0) {
        if (seen == 0) grown = bin_box[b];
        else extend(grown, bin_box[b]);
        seen += count[b];
      }
      right_count[b] = seen;
      right_area[b] = seen == 0 ? 0 : half_area(grown);
    }
    seen = 0;
    for (std::size_t b = 0; b + 1 < kBins; ++b) {
      if (count[b] > 0) {
        if (seen == 0) grown = bin_box[b];
        else extend(grown, bin_box[b]);
        seen += count[b];
      }
      if (seen < least || right_count[b + 1] < least) continue;
      const double cost = half_area(grown) * seen + right_area[b + 1] * right_count[b + 1];
      if (cost < best.cost) best = {cost, axis, b, lo, width};
    }
  }
  if (!(best.cost < std::numeric_limits<double>::infinity())) return begin;
  const auto middle = std::partition(order_.begin() + begin, order_.begin() + end, [&](std::uint32_t t) {
    return bin_of(centres[t][best.axis], best.lo, best.width) <= best.last_left_bin;
  });
  return static_cast<std::uint32_t>(middle - order_.begin());
}

std::uint64_t TriangleTree::for_each_overlapping_pair(
    const std::function<bool(std::uint32_t, std::uint32_t)>& visit) const {
  std::uint64_t pairs = 0;
  if (nodes_.empty()) return pairs;
  // Depth-first over pairs of nodes (a, b), a == b meaning pairs inside a.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
  auto leaf_pairs = [&](const Node& a, const Node& b, bool same) {
    for (std::uint32_t i = a.begin; i < a.end; ++i)
      for (std::uint32_t j = same ? i + 1 : b.begin; j < b.end; ++j) {
        const std::uint32_t s = order_[i];
        const std::uint32_t t = order_[j];
        if (!overlap(boxes_[s], boxes_[t])) continue;
        ++pairs;
        if (visit(std::min(s, t), std::max(s, t))) return true;
      }
    return false;
  };
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const Node& a = nodes_[ia];
    const Node& b = nodes_[ib];
    if (ia == ib) {
      if (is_leaf(a)) {
        if (leaf_pairs(a, a, true)) return pairs;
      } else {
        stack.push_back({ia + 1, a.right});
        stack.push_back({a.right, a.right});
        stack.push_back({ia + 1, ia + 1});
      }
      continue;
    }
    if (!overlap(a.box, b.box)) continue;
    if (is_leaf(a) && is_leaf(b)) {
      if (leaf_pairs(a, b, false)) return pairs;
    } else if (is_leaf(b) || (!is_leaf(a) && a.end - a.begin >= b.end - b.begin)) {
      stack.push_back({a.right, ib});
      stack.push_back({ia + 1, ib});
    } else {
      stack.push_back({ia, b.right});
      stack.push_back({ia, ib + 1});
    }
  }
  return pairs;
}

void TriangleTree::for_each_overlapping(const Box& box,
                                        const std::function<void(std::uint32_t)>& visit) const {
  if (nodes_.empty()) return;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[stack.back()];
    const std::uint32_t index = stack.back();
    stack.pop_back();
    if (!overlap(n.box, box)) continue;
    if (is_leaf(n)) {
      for (std::uint32_t i = n.begin; i < n.end; ++i)
        if (overlap(boxes_[order_[i]], box)) visit(order_[i]);
    } else {
      stack.push_back(n.right);
      stack.push_back(index + 1);
    }
  }
}

void TriangleTree::for_each_on_ray(const Vec3& p, const Vec3& d,
                                   const std::function<bool(std::uint32_t)>& visit) const {
  if (nodes_.empty()) return;
  // The double filter answers most boxes; a ray beyond the doubles' range
  // (or with a direction coordinate too small for them) takes the exact test.
  const RayEnclosure enclosure = enclose(p, d);
  auto meets = [&](const Box& box) {
    return enclosure.usable ? ray_may_meet_box(enclosure, box) : ray_meets_box(p, d, box);
  };
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const std::uint32_t index = stack.back();
    const Node& n = nodes_[index];
    stack.pop_back();
    if (!meets(n.box)) continue;
    if (is_leaf(n)) {
      for (std::uint32_t i = n.begin; i < n.end; ++i)
        if (meets(boxes_[order_[i]]) && visit(order_[i])) return;
    } else {
      stack.push_back(n.right);
      stack.push_back(index + 1);
    }
  }
}

}  // namespace cvms::detail
