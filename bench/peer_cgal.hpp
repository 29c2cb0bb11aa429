// SPDX-License-Identifier: MIT
/// \file
/// CGAL as a benchmark peer (bench only; never linked into the library):
/// CGAL::convex_hull_3 and CGAL::halfspace_intersection_3 with the
/// exact-constructions kernel (Epeck). Points and planes are converted
/// exactly from cvms's rationals once, before timing; the interface hides
/// every CGAL type from the benchmark sources.
#pragma once

#include <cstddef>
#include <memory>
#include <span>

#include "cvms/halfspaces.hpp"
#include "cvms/vec.hpp"

namespace cvms_bench {

/// Counts of one CGAL hull.
struct CgalHull {
  std::size_t triangles = 0;  ///< faces of the Surface_mesh: convex_hull_3 triangulates every facet
  std::size_t vertices = 0;   ///< hull vertices
};

/// A point set held as exact CGAL points.
class CgalExactPoints {
 public:
  /// Exact copies of `points`.
  explicit CgalExactPoints(std::span<const cvms::Vec3> points);
  /// The pairwise sums a + b for every a in `a` and b in `b`, exactly.
  CgalExactPoints(std::span<const cvms::Vec3> a, std::span<const cvms::Vec3> b);
  ~CgalExactPoints();
  CgalExactPoints(const CgalExactPoints&) = delete;
  CgalExactPoints& operator=(const CgalExactPoints&) = delete;

  /// Number of points held.
  [[nodiscard]] std::size_t size() const;
  /// CGAL::convex_hull_3 of the points into a Surface_mesh (exact).
  [[nodiscard]] CgalHull convex_hull() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Counts of one CGAL half-space intersection.
struct CgalIntersection {
  std::size_t faces = 0;     ///< faces of the Surface_mesh (the dual hull's triangles: facets triangulated)
  std::size_t vertices = 0;  ///< vertices of the intersection
};

/// Half-spaces a·x <= b held as exact CGAL planes a·x − b = 0 (CGAL keeps
/// each plane's negative side), with a strictly interior point.
class CgalExactPlanes {
 public:
  /// Exact copies of `rows`; `interior` strictly inside every one.
  CgalExactPlanes(std::span<const cvms::HalfspaceRow> rows, const cvms::Vec3& interior);
  ~CgalExactPlanes();
  CgalExactPlanes(const CgalExactPlanes&) = delete;
  CgalExactPlanes& operator=(const CgalExactPlanes&) = delete;

  /// CGAL::halfspace_intersection_3 of the planes into a Surface_mesh, about
  /// the interior point (exact: Epeck).
  [[nodiscard]] CgalIntersection intersect() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cvms_bench
