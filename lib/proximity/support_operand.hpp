// SPDX-License-Identifier: MIT
// The operand of the exact GJK as it sees it: a finite set of points (the
// vertices of a convex set) and a support walk on them. GJK needs nothing
// else (gjk.cpp), so one loop serves a placed polyhedron and a convex set of
// any dimension: the polyhedron walks its mesh (support.cpp applies the
// placement to the direction), a point, a segment or a polygon walks its
// cycle (support_walk.hpp, CycleGraph).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "approx.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/proximity.hpp"
#include "cvms/sign.hpp"
#include "support_walk.hpp"

namespace cvms::detail {

/// The vertices of a point, a segment or a polygon with the approximations
/// the filters need (ConvexSet keeps none), and their graph.
struct VertexCycle {
  std::vector<Vec3> points;
  std::vector<ApproxVec3> approx;
  VertexCycle() = default;
  explicit VertexCycle(const ConvexSet& s);
  [[nodiscard]] CycleGraph graph() const noexcept { return {points, approx}; }
};

class SupportOperand {
 public:
  /// A view of p (which must outlive the operand).
  explicit SupportOperand(const PlacedPolyhedron& p);
  /// Not from a temporary: the operand keeps a pointer to it.
  explicit SupportOperand(PlacedPolyhedron&&) = delete;
  /// p unmoved, viewed (no PlacedPolyhedron to build: its identity map is
  /// 21 rationals).
  explicit SupportOperand(const ConvexPolyhedron& p) : solid_(&p) {}
  explicit SupportOperand(ConvexPolyhedron&&) = delete;
  /// A set of dimension 3 is viewed (it must outlive the operand); a lower
  /// one has its few vertices and their approximations copied, because
  /// ConvexSet keeps no approximations for the filters.
  /// \pre s is not empty.
  explicit SupportOperand(const ConvexSet& s);

  /// A vertex maximising <x, u> (sense positive) or minimising it (sense
  /// negative) over the (moved) set, climbing from `start`, a valid vertex.
  [[nodiscard]] VertexId support(Vec3Ref u, Sign sense, VertexId start) const;
  /// The (moved) position of vertex v.
  [[nodiscard]] Vec3 position(VertexId v) const;
  /// The position of vertex v: the stored one, viewed, when the set is not
  /// moved (the exact queries' hot paths copy no rationals then), else the
  /// moved one, made in `moved`.
  [[nodiscard]] const Vec3& position_view(VertexId v, std::optional<Vec3>& moved) const;

  /// Heuristics for double_gjk.cpp, in plain doubles (no error bound: they
  /// only propose candidates that exact arithmetic then checks). A vertex
  /// maximising <x, u> as far as rounding tells, climbing from `start`; it
  /// stops at the first vertex with no neighbour better in doubles (NaN
  /// compares false, so the climb always ends).
  [[nodiscard]] VertexId approx_support(const std::array<double, 3>& u, VertexId start) const;
  /// The (moved) position of vertex v in doubles, rounded (maybe infinite).
  [[nodiscard]] std::array<double, 3> approx_position(VertexId v) const;

 private:
  // Views, not copies (a PlacedPolyhedron holds 21 rationals): the solid
  // walked, its placement when it has one, else the cycle.
  const ConvexPolyhedron* solid_ = nullptr;
  const PlacedPolyhedron* placed_ = nullptr;
  VertexCycle cycle_;  // when not a polyhedron
  // The placement's doubles (the exact placement is made of doubles, so
  // these are its entries, not roundings); identity when not placed.
  double linear_[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double translation_[3] = {0, 0, 0};
  void copy_placement();
};

/// out := (a's vertex va) - (b's vertex vb), both moved; unmoved vertices
/// are read in place, not copied.
void subtract_positions(Vec3& out, const SupportOperand& a, VertexId va, const SupportOperand& b, VertexId vb);

}  // namespace cvms::detail
