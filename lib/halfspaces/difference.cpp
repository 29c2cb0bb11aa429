// SPDX-License-Identifier: MIT
// The Pontryagin difference A ⊖ B = {x : x + B ⊆ A}. x + B ⊆ A iff every
// row n·y <= d of A holds on x + B, i.e. n·x + h_B(n) <= d with h_B the
// support function of B; an equality of A is two opposite rows. So A ⊖ B is
// the intersection of the shifted rows of A (halfspaces.hpp).
#include <utility>

#include "cvms/error.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/proximity.hpp"
#include "cvms/set_sum.hpp"
#include "progress_reporter.hpp"
#include "support_operand.hpp"

namespace cvms {

namespace {

// h_B by a walk, warm-started at the last answer: the proximity layer's
// support operand, a hill-climb over a polyhedron's edges or along a
// polygon's (segment's, point's) vertex cycle. The rows of a facet list come
// in no particular order, so a start anywhere must be (and is) correct; a
// good one only shortens the climb, and neighbouring normals have
// neighbouring maximisers, so a sweep costs O(vertices + rows) steps, not a
// scan of B per row.
class SupportFunction {
 public:
  explicit SupportFunction(const ConvexSet& b) : operand_(b) {}
  Rational operator()(const Vec3& n) {
    const ApproxVec3 n_approx = ApproxVec3::of(n);
    start_ = operand_.support(Vec3Ref{n, n_approx}, Sign::positive, start_);
    return dot(n, operand_.position(start_));
  }

 private:
  detail::SupportOperand operand_;
  VertexId start_ = VertexId(0);
};

// Rows shifted between two progress reports: each costs a short climb on B.
constexpr std::size_t rows_per_report = 1024;

}  // namespace

ConvexSet pontryagin_difference(const ConvexSet& a, const ConvexSet& b) {
  return pontryagin_difference(a, b, ProgressCallback());
}

ConvexSet pontryagin_difference(const ConvexSet& a, const ConvexSet& b, const ProgressCallback& progress) {
  if (b.empty()) {
    throw Error(ErrorCategory::invalid_argument,
                "pontryagin_difference: B is empty (the difference would be all of space)");
  }
  if (a.empty()) return {};
  const HalfspaceSystem rows = to_halfspaces(a);
  std::vector<HalfspaceRow> shifted;
  shifted.reserve(rows.inequalities.size() + 2 * rows.equalities.size());
  SupportFunction h(b);
  detail::ProgressReporter reporter(detail::callback_of(progress));
  reporter.begin("difference: rows", rows.inequalities.size() + 2 * rows.equalities.size());
  const auto shift = [&](const Vec3& n, const Rational& d) {
    shifted.push_back({n, d - h(n)});
    if (shifted.size() % rows_per_report == 0) reporter.advance(rows_per_report);
  };
  for (const HalfspaceRow& r : rows.inequalities) shift(r.normal, r.offset);
  for (const HalfspaceRow& r : rows.equalities) {
    shift(r.normal, r.offset);
    shift(-r.normal, -r.offset);
  }
  reporter.end();
  return from_halfspaces(shifted, progress);
}

ConvexSet minkowski_difference(const ConvexSet& a, const ConvexSet& b, const Options& options) {
  return minkowski_sum(a, b.reflected(), options);
}

}  // namespace cvms
