// SPDX-License-Identifier: MIT
// penetration(): the exact GJK decides whether the operands intersect
// (gjk.cpp); if they do, its final simplex starts the exact EPA (epa.cpp),
// which finds the facet of M = A + (-B) nearest to the origin, and every
// facet tied with it, from support points of M only: M is never built. The
// answers are those of the whole-sum scan (penetration_by_sum.cpp,
// the tests' reference), tie rule included: the smallest primitive normal
// among the tied facets, so the answer does not depend on how either method
// numbers facets. The witnesses come from the EPA's polytope too (epa.cpp),
// so they may differ from the whole-sum version's (a contact is rarely
// unique); both are a point of A and a point of B whose difference is the
// translation. Convex sets whose M is flat have no facet: the EPA says so
// and the whole-sum version gives its answer, which needs only the flat sum.
#include <optional>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "epa.hpp"
#include "penetration_by_sum.hpp"
#include "penetration_result.hpp"
#include "query_operands.hpp"

namespace cvms {
namespace {

// The exact GJK's outcome and the answer it gives when they are apart (or,
// provisionally, when they intersect).
struct Start {
  detail::GjkOutcome gjk;
  PenetrationResult r;
};

Start start(const detail::SupportOperand& a, const detail::SupportOperand& b) {
  Start s{detail::exact_gjk(a, b, detail::GjkGoal::distance), {}};
  if (s.gjk.intersect) {
    s.r.intersect = true;  // the EPA gives the witnesses
    return s;
  }
  s.r = detail::penetration_from_distance(detail::distance_from(a, s.gjk));
  return s;
}

void finish(PenetrationResult& r, detail::NearestFacet f) {
  detail::set_depth(r, std::move(f.direction), std::move(f.offset));
  r.witness_a = std::move(f.witness_a);
  r.witness_b = std::move(f.witness_b);
}

// The moved operand is a polyhedron, as the answer assumes (and as the
// whole-sum version required when it built it).
void check_invertible(const PlacedPolyhedron& p) {
  if (p.is_placed() && sgn(p.linear().determinant()) == 0)
    throw Error(ErrorCategory::invalid_argument, "penetration: singular linear map in a placement");
}

}  // namespace

PenetrationResult penetration(const PlacedPolyhedron& a, const PlacedPolyhedron& b) {
  detail::check_operands(a, b, "penetration");
  const detail::SupportOperand sa(a);
  const detail::SupportOperand sb(b);
  Start s = start(sa, sb);
  if (!s.r.intersect) return s.r;
  check_invertible(a);
  check_invertible(b);
  // Both solid, so M is: the EPA answers.
  finish(s.r, *detail::epa_nearest_facet(sa, sb, s.gjk));
  return s.r;
}

PenetrationResult penetration(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  detail::check_operands(a, b, "penetration");
  const detail::SupportOperand sa(a);
  const detail::SupportOperand sb(b);
  Start s = start(sa, sb);
  if (!s.r.intersect) return s.r;
  finish(s.r, *detail::epa_nearest_facet(sa, sb, s.gjk));  // both solid: the EPA answers
  return s.r;
}

PenetrationResult penetration(const ConvexSet& a, const ConvexSet& b) {
  detail::check_operands(a, b, "penetration");
  const detail::SupportOperand sa(a);
  const detail::SupportOperand sb(b);
  Start s = start(sa, sb);
  if (!s.r.intersect) return s.r;
  std::optional<detail::NearestFacet> f = detail::epa_nearest_facet(sa, sb, s.gjk);
  if (!f) return detail::penetration_by_sum(a, b);  // flat M
  finish(s.r, *std::move(f));
  return s.r;
}

}  // namespace cvms
