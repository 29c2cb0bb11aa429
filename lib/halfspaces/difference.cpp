// SPDX-License-Identifier: MIT
// The Pontryagin difference A ⊖ B = {x : x + B ⊆ A}. x + B ⊆ A iff every
// row n·y <= d of A holds on x + B, i.e. n·x + h_B(n) <= d with h_B the
// support function of B; an equality of A is two opposite rows. So A ⊖ B is
// the intersection of the shifted rows of A (halfspaces.hpp).
#include <optional>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/proximity.hpp"
#include "cvms/set_sum.hpp"
#include "cycle_support.hpp"

namespace cvms {

namespace {

// h_B by a walk, warm-started at the last answer: on a polyhedron the
// proximity layer's hill-climb over its edges, on a polygon, segment or
// point the climb along its vertex cycle (cycle_support.hpp). The rows of a
// facet list come in no particular order, so a start anywhere must be (and
// is) correct; a good one only shortens the climb.
class SupportFunction {
 public:
  explicit SupportFunction(const ConvexSet& b) : b_(b) {
    if (b.dimension() < 3) cycle_.emplace(b.vertices());
  }
  Rational operator()(const Vec3& n) {
    if (b_.dimension() == 3) {
      SupportResult r = support(b_.polyhedron(), n, start_);
      start_ = r.vertex;
      return std::move(r.value);
    }
    return dot(n, cycle_->cycle()[cycle_->maximiser(n)]);
  }

 private:
  const ConvexSet& b_;
  std::optional<detail::CycleSupport> cycle_;
  VertexId start_ = VertexId(0);
};

}  // namespace

ConvexSet pontryagin_difference(const ConvexSet& a, const ConvexSet& b) {
  if (b.empty()) {
    throw Error(ErrorCategory::invalid_argument,
                "pontryagin_difference: B is empty (the difference would be all of space)");
  }
  if (a.empty()) return {};
  const HalfspaceSystem rows = to_halfspaces(a);
  std::vector<HalfspaceRow> shifted;
  shifted.reserve(rows.inequalities.size() + 2 * rows.equalities.size());
  SupportFunction h(b);
  const auto shift = [&](const Vec3& n, const Rational& d) { shifted.push_back({n, d - h(n)}); };
  for (const HalfspaceRow& r : rows.inequalities) shift(r.normal, r.offset);
  for (const HalfspaceRow& r : rows.equalities) {
    shift(r.normal, r.offset);
    shift(-r.normal, -r.offset);
  }
  return from_halfspaces(shifted);
}

ConvexSet minkowski_difference(const ConvexSet& a, const ConvexSet& b, const Options& options) {
  return minkowski_sum(a, b.reflected(), options);
}

}  // namespace cvms
