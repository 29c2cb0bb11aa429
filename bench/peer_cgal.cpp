// SPDX-License-Identifier: MIT
#include "peer_cgal.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <type_traits>
#include <vector>

namespace cvms_bench {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using ExactNumber = Kernel::FT::Exact_type;

// Epeck's exact number type depends on how CGAL was configured (gmpxx's
// mpq_class, CGAL::Gmpq or Boost.Multiprecision over GMP); every one of
// them takes a GMP rational, so the conversion is exact either way.
Kernel::FT exact(const cvms::Rational& q) {
  if constexpr (std::is_constructible_v<ExactNumber, const mpq_class&>) {
    return Kernel::FT(ExactNumber(q));
  } else {
    return Kernel::FT(ExactNumber(q.get_mpq_t()));
  }
}

Point exact(const cvms::Vec3& v) { return Point(exact(v.x), exact(v.y), exact(v.z)); }

}  // namespace

struct CgalExactPoints::Impl {
  std::vector<Point> points;
};

CgalExactPoints::CgalExactPoints(std::span<const cvms::Vec3> points) : impl_(std::make_unique<Impl>()) {
  impl_->points.reserve(points.size());
  for (const cvms::Vec3& p : points) impl_->points.push_back(exact(p));
}

CgalExactPoints::CgalExactPoints(std::span<const cvms::Vec3> a, std::span<const cvms::Vec3> b)
    : impl_(std::make_unique<Impl>()) {
  impl_->points.reserve(a.size() * b.size());
  for (const cvms::Vec3& p : a)
    for (const cvms::Vec3& q : b) impl_->points.push_back(exact(p + q));
}

CgalExactPoints::~CgalExactPoints() = default;

std::size_t CgalExactPoints::size() const { return impl_->points.size(); }

CgalHull CgalExactPoints::convex_hull() const {
  CGAL::Surface_mesh<Point> mesh;
  CGAL::convex_hull_3(impl_->points.begin(), impl_->points.end(), mesh);
  return {mesh.number_of_faces(), mesh.number_of_vertices()};
}

}  // namespace cvms_bench
