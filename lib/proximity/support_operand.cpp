// SPDX-License-Identifier: MIT
// SupportOperand (support_operand.hpp): which graph the support walk climbs.
// A placement x -> R x + t is applied to the direction, not to the
// polyhedron: max over x in P of <R x + t, u> is reached where <x, R^T u> is,
// for any linear R (support.cpp says more).
#include "support_operand.hpp"

#include "dyadic.hpp"

namespace cvms::detail {

VertexCycle::VertexCycle(const ConvexSet& s) : points(s.vertices()) {
  approx.reserve(points.size());
  for (const Vec3& x : points) approx.push_back(ApproxVec3::of(x));
}

SupportOperand::SupportOperand(const PlacedPolyhedron& p)
    : solid_(&p.polyhedron()), placed_(p.is_placed() ? &p : nullptr) {
  copy_placement();
}

SupportOperand::SupportOperand(const ConvexSet& s) {
  if (s.dimension() == 3)
    solid_ = &s.polyhedron();
  else
    cycle_ = VertexCycle(s);
}

void SupportOperand::copy_placement() {
  if (placed_ == nullptr) return;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) linear_[i][j] = placed_->linear().m[i][j].get_d();
    translation_[i] = placed_->translation()[i].get_d();
  }
}

VertexId SupportOperand::support(Vec3Ref u, Sign sense, VertexId start) const {
  if (solid_ == nullptr) return climb_to_maximum(cycle_.graph(), u, start, sense);
  const PolyhedronGraph graph{*solid_};
  if (placed_ == nullptr) return climb_to_maximum(graph, u, start, sense);
  const Vec3 local = placed_->linear_transposed() * u.exact;
  const ApproxVec3 approx = ApproxVec3::of(local);
  return climb_to_maximum(graph, Vec3Ref{local, approx}, start, sense);
}

Vec3 SupportOperand::position(VertexId v) const {
  if (placed_ != nullptr) return placed_->position(v);
  return solid_ != nullptr ? solid_->vertex(v) : cycle_.points[v.index()];
}

const Vec3& SupportOperand::position_view(VertexId v, std::optional<Vec3>& moved) const {
  if (placed_ != nullptr) return moved.emplace(placed_->position(v));
  return solid_ != nullptr ? solid_->vertex(v) : cycle_.points[v.index()];
}

void subtract_positions(Vec3& out, const SupportOperand& a, VertexId va, const SupportOperand& b, VertexId vb) {
  std::optional<Vec3> moved_a;
  std::optional<Vec3> moved_b;
  const Vec3& pa = a.position_view(va, moved_a);
  const Vec3& pb = b.position_view(vb, moved_b);
  for (int i = 0; i < 3; ++i) subtract_into(out[i], pa[i], pb[i]);  // no gcd for dyadic coordinates
}

}  // namespace cvms::detail

namespace cvms::detail {
namespace {

double approx_dot(const ApproxVec3& x, const std::array<double, 3>& u) {
  return x.x.value * u[0] + x.y.value * u[1] + x.z.value * u[2];
}

template <class Graph>
VertexId approx_climb(const Graph& g, const std::array<double, 3>& u, VertexId start) {
  VertexId v = start;
  double here = approx_dot(g.ref(v).approx, u);
  for (bool improved = true; improved;) {
    improved = false;
    VertexId better;
    double better_value = here;
    g.for_each_neighbour(v, [&](VertexId w) {
      const double value = approx_dot(g.ref(w).approx, u);
      if (value > better_value) {
        better = w;
        better_value = value;
      }
    });
    if (better.is_valid()) {
      v = better;
      here = better_value;
      improved = true;
    }
  }
  return v;
}

}  // namespace

VertexId SupportOperand::approx_support(const std::array<double, 3>& u, VertexId start) const {
  if (solid_ == nullptr) return approx_climb(cycle_.graph(), u, start);
  // max <R x + t, u> is reached where <x, R^T u> is.
  std::array<double, 3> local{};
  for (int j = 0; j < 3; ++j) local[j] = linear_[0][j] * u[0] + linear_[1][j] * u[1] + linear_[2][j] * u[2];
  return approx_climb(PolyhedronGraph{*solid_}, local, start);
}

std::array<double, 3> SupportOperand::approx_position(VertexId v) const {
  const ApproxVec3& x = solid_ != nullptr ? vertex_approx(*solid_, v) : cycle_.approx[v.index()];
  const double p[3] = {x.x.value, x.y.value, x.z.value};
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i)
    out[i] = linear_[i][0] * p[0] + linear_[i][1] * p[1] + linear_[i][2] * p[2] + translation_[i];
  return out;
}

}  // namespace cvms::detail
