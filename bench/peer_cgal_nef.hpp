// SPDX-License-Identifier: MIT
/// \file
/// CGAL's Nef polyhedra as a benchmark peer for sums of solids that need not
/// be convex (bench only; never linked into the library):
/// CGAL::minkowski_sum_3 of two Nef_polyhedron_3 with the exact-constructions
/// kernel (Epeck), exact like cvms. The operands are converted exactly from
/// cvms's rationals into CGAL surface meshes once, before timing; the
/// interface hides every CGAL type from the benchmark sources.
#pragma once

#include <cstddef>
#include <memory>

#include "cvms/solid.hpp"

namespace cvms_bench {

/// Counts of one Nef sum.
struct CgalNefSum {
  std::size_t vertices = 0;  ///< vertices of the Nef polyhedron
  std::size_t facets = 0;    ///< its facets (CGAL's halffacet pairs)
  std::size_t volumes = 0;   ///< its volumes, the unbounded outer one included
  bool simple = false;       ///< whether CGAL finds it a 2-manifold (Nef is_simple)
};

/// A solid held as an exact CGAL surface mesh (its triangles).
class CgalNefOperand {
 public:
  /// Exact copy of the solid's triangles.
  explicit CgalNefOperand(const cvms::Solid& solid);
  ~CgalNefOperand();
  CgalNefOperand(const CgalNefOperand&) = delete;
  CgalNefOperand& operator=(const CgalNefOperand&) = delete;

  /// CGAL::minkowski_sum_3 of the Nef polyhedra of `*this` and `other`, the
  /// conversions of both meshes to Nef polyhedra included (minkowski_sum_3
  /// decomposes and so modifies its operands: each call makes its own).
  [[nodiscard]] CgalNefSum minkowski_sum(const CgalNefOperand& other) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cvms_bench
