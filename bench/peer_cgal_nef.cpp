// SPDX-License-Identifier: MIT
#include "peer_cgal_nef.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/minkowski_sum_3.h>

#include <vector>

#include "cgal_exact.hpp"

namespace cvms_bench {
namespace {

using cgal::exact;
using Point = cgal::Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Nef = CGAL::Nef_polyhedron_3<cgal::Kernel>;

}  // namespace

struct CgalNefOperand::Impl {
  Mesh mesh;
};

CgalNefOperand::CgalNefOperand(const cvms::Solid& solid) : impl_(std::make_unique<Impl>()) {
  std::vector<Mesh::Vertex_index> index;
  index.reserve(solid.vertices().size());
  for (const cvms::Vec3& v : solid.vertices())
    index.push_back(impl_->mesh.add_vertex(exact(v)));
  for (const auto& t : solid.triangles()) impl_->mesh.add_face(index[t[0]], index[t[1]], index[t[2]]);
}

CgalNefOperand::~CgalNefOperand() = default;

CgalNefSum CgalNefOperand::minkowski_sum(const CgalNefOperand& other) const {
  Nef a(impl_->mesh);
  Nef b(other.impl_->mesh);
  const Nef sum = CGAL::minkowski_sum_3(a, b);
  return {sum.number_of_vertices(), sum.number_of_facets(), sum.number_of_volumes(), sum.is_simple()};
}

}  // namespace cvms_bench
