// SPDX-License-Identifier: MIT
// support(): the public support query, and the placed operand it works on.
// The walk and why it is correct are in support_walk.hpp; a placement
// x -> R x + t is applied to the direction instead of the polyhedron:
// max over x in P of <R x + t, u> = max over x in P of <x, R^T u> + <t, u>,
// for any linear map R (exactly orthogonal or not), so the walk runs on P
// itself with the direction R^T u.
#include <cmath>
#include <string>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "query_operands.hpp"
#include "support_walk.hpp"

namespace cvms {
namespace {

Rational exact_finite(double x, const char* what) {
  if (!std::isfinite(x)) throw Error(ErrorCategory::invalid_argument, std::string("placement: ") + what + " is not finite");
  return Rational(x);
}

void check_operand(const ConvexPolyhedron& p, const char* who) {
  if (p.num_vertices() == 0) throw Error(ErrorCategory::invalid_argument, std::string(who) + ": empty polyhedron");
}

}  // namespace

PlacedPolyhedron::PlacedPolyhedron(const ConvexPolyhedron& p, const Placement& placement)
    : polyhedron_(&p), placed_(true) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      linear_.m[i][j] = exact_finite(placement.rotation[i][j], "a rotation entry");
      transposed_.m[j][i] = linear_.m[i][j];
    }
    translation_[i] = exact_finite(placement.translation[i], "a translation entry");
  }
}

Vec3 PlacedPolyhedron::position(VertexId v) const {
  const Vec3& x = polyhedron_->vertex(v);
  return placed_ ? linear_ * x + translation_ : x;
}

ConvexPolyhedron PlacedPolyhedron::materialized() const {
  return placed_ ? polyhedron_->transformed(linear_, translation_) : *polyhedron_;
}

namespace detail {

void check_operands(const PlacedPolyhedron& a, const PlacedPolyhedron& b, const char* who) {
  check_operand(a.polyhedron(), who);
  check_operand(b.polyhedron(), who);
}

void check_operands(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const char* who) {
  check_operand(a, who);
  check_operand(b, who);
}

void check_operands(const ConvexSet& a, const ConvexSet& b, const char* who) {
  for (const auto& [set, name] : {std::pair{&a, "A"}, std::pair{&b, "B"}})
    if (set->empty()) throw Error(ErrorCategory::invalid_argument, std::string(who) + ": operand " + name + " is the empty set");
}

}  // namespace detail

SupportResult support(const PlacedPolyhedron& p, const Vec3& u, VertexId start, bool want_face) {
  const ConvexPolyhedron& poly = p.polyhedron();
  check_operand(poly, "support");
  if (is_zero(u)) throw Error(ErrorCategory::invalid_argument, "support: zero direction");
  if (!start.is_valid() || start.index() >= poly.num_vertices())
    throw Error(ErrorCategory::invalid_argument,
                "support: start vertex " + std::to_string(start.index()) + " is not a vertex (the polyhedron has " +
                    std::to_string(poly.num_vertices()) + ")");
  const Vec3 local = p.is_placed() ? p.linear_transposed() * u : u;
  // A singular placement may map u to zero: then every point maximises and
  // there is no face to name.
  if (is_zero(local))
    throw Error(ErrorCategory::invalid_argument,
                "support: the placement's linear part maps the direction to zero (it is singular)");
  const ApproxVec3 approx = ApproxVec3::of(local);
  const Vec3Ref dir{local, approx};
  const detail::PolyhedronGraph graph{poly};
  SupportResult r;
  r.vertex = detail::climb_to_maximum(graph, dir, start);
  r.point = p.position(r.vertex);
  r.value = dot(r.point, u);
  if (want_face) {
    r.face.vertices = detail::maximising_face(graph, dir, r.vertex);
    r.face.dimension = r.face.vertices.size() >= 3 ? 2 : static_cast<int>(r.face.vertices.size()) - 1;
    if (r.face.dimension == 2) {
      // The facet at the maximiser whose outward normal has the direction of
      // the (local) direction: parallel and pointing the same way.
      const Mesh& m = poly.mesh();
      for (HalfedgeId h : m.outgoing_halfedges(r.vertex)) {
        const FaceId f = m.face(h);
        const Vec3Ref n = detail::normal_ref(poly, f);
        if (sign_dot(n, dir) == Sign::positive && is_parallel(n, dir)) {
          r.face.facet = f;
          break;
        }
      }
    }
  }
  return r;
}

}  // namespace cvms
