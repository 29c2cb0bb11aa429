// SPDX-License-Identifier: MIT
/// \file
/// Exact conversion of cvms's rationals to CGAL's exact-constructions kernel
/// (Epeck), shared by the CGAL peers (peer_cgal.cpp, peer_cgal_nef.cpp).
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <type_traits>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms_bench::cgal {

/// The kernel of every CGAL peer.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;

/// q as a number of the kernel, exactly. Epeck's exact number type depends on
/// how CGAL was configured (gmpxx's mpq_class, CGAL::Gmpq or
/// Boost.Multiprecision over GMP); every one of them takes a GMP rational.
inline Kernel::FT exact(const cvms::Rational& q) {
  using ExactNumber = Kernel::FT::Exact_type;
  if constexpr (std::is_constructible_v<ExactNumber, const mpq_class&>) {
    return Kernel::FT(ExactNumber(q));
  } else {
    return Kernel::FT(ExactNumber(q.get_mpq_t()));
  }
}

/// v as a point of the kernel, exactly.
inline Kernel::Point_3 exact(const cvms::Vec3& v) { return {exact(v.x), exact(v.y), exact(v.z)}; }

}  // namespace cvms_bench::cgal
