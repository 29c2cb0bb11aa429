// SPDX-License-Identifier: MIT
#include "peer_cgal.hpp"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/version.h>

#if CGAL_VERSION_NR < 1060000000
#include <boost/optional.hpp>
#else
#include <optional>
#endif

#include <vector>

#include "cgal_exact.hpp"

namespace cvms_bench {
namespace {

using cgal::exact;
using Kernel = cgal::Kernel;
using Point = Kernel::Point_3;

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

struct CgalExactPlanes::Impl {
  std::vector<Kernel::Plane_3> planes;
  Point interior;
};

CgalExactPlanes::CgalExactPlanes(std::span<const cvms::HalfspaceRow> rows, const cvms::Vec3& interior)
    : impl_(std::make_unique<Impl>()) {
  impl_->planes.reserve(rows.size());
  for (const cvms::HalfspaceRow& r : rows)
    impl_->planes.emplace_back(exact(r.normal.x), exact(r.normal.y), exact(r.normal.z), exact(-r.offset));
  impl_->interior = exact(interior);
}

CgalExactPlanes::~CgalExactPlanes() = default;

CgalIntersection CgalExactPlanes::intersect() const {
  CGAL::Surface_mesh<Point> mesh;
  // CGAL 6 takes the interior point as std::optional, earlier versions as boost::optional.
#if CGAL_VERSION_NR < 1060000000
  const boost::optional<Point> origin(impl_->interior);
#else
  const std::optional<Point> origin(impl_->interior);
#endif
  CGAL::halfspace_intersection_3(impl_->planes.begin(), impl_->planes.end(), mesh, origin);
  return {mesh.number_of_faces(), mesh.number_of_vertices()};
}

}  // namespace cvms_bench
