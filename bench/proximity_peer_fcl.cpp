// SPDX-License-Identifier: MIT
// FCL rows of cvms_proximity_bench (bench-only peer, off by default:
// CVMS_BENCH_PEERS=ON with Debian's libfcl-dev): fcl::distance (GJK) and
// fcl::collide with contacts (GJK/EPA, libccd) on fcl::Convexd copies of the
// exact rows' operands (proximity_operands.hpp), the vertices rounded to
// doubles (the shapes' coordinates are doubles, so nothing is lost). Each row
// also reports FCL's error against the exact answer: the relative error of
// its distance or depth against the correctly rounded exact one, and for
// contacts whether its normal is off the exact direction by more than 1e-6
// radians (direction_wrong = 1).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include "cvms/proximity.hpp"
#include "proximity_operands.hpp"

namespace {

std::shared_ptr<fcl::CollisionGeometryd> to_fcl(const cvms::ConvexPolyhedron& p) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  for (cvms::VertexId v : p.mesh().vertices()) {
    const cvms::Vec3& x = p.vertex(v);
    vertices->emplace_back(cvms::to_double_nearest(x.x), cvms::to_double_nearest(x.y), cvms::to_double_nearest(x.z));
  }
  auto faces = std::make_shared<std::vector<int>>();
  for (cvms::FaceId f : p.mesh().faces()) {
    faces->push_back(static_cast<int>(p.mesh().degree(f)));
    for (cvms::HalfedgeId h : p.mesh().face_halfedges(f)) faces->push_back(static_cast<int>(p.mesh().from(h).index()));
  }
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(p.num_facets()), faces);
}

struct FclPair {
  fcl::CollisionObjectd a;
  fcl::CollisionObjectd b;
};

FclPair fcl_pair(const cvms_bench::Operands& o) {
  return {fcl::CollisionObjectd(to_fcl(o.a)), fcl::CollisionObjectd(to_fcl(o.b))};
}

double relative_error(double value, double exact) {
  if (exact == 0.0) return std::abs(value);
  return std::abs(value - exact) / exact;
}

void label(benchmark::State& state, const cvms_bench::Operands& o) {
  state.SetLabel("FCL " + o.label + " " + cvms_bench::kPlacements[state.range(1)] +
                 (state.range(2) == static_cast<int>(fcl::GST_INDEP) ? " (GST_INDEP)" : ""));
}

void BM_FclDistance(benchmark::State& state) {
  const cvms_bench::Operands& o = cvms_bench::operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  label(state, o);
  FclPair pair = fcl_pair(o);
  fcl::DistanceRequestd request;
  request.gjk_solver_type = static_cast<fcl::GJKSolverType>(state.range(2));
  fcl::DistanceResultd result;
  double distance = 0;
  for (auto _ : state) {
    result.clear();
    distance = fcl::distance(&pair.a, &pair.b, request, result);
    benchmark::DoNotOptimize(distance);
  }
  const double exact = cvms::nearest_double_sqrt(cvms::squared_distance(o.a, o.b).squared_distance);
  state.counters["fcl_distance"] = distance;
  state.counters["exact_distance"] = exact;
  state.counters["rel_error"] = relative_error(std::max(distance, 0.0), exact);
}

void BM_FclPenetration(benchmark::State& state) {
  const cvms_bench::Operands& o = cvms_bench::operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  label(state, o);
  FclPair pair = fcl_pair(o);
  fcl::CollisionRequestd request(1, true);
  fcl::CollisionResultd result;
  for (auto _ : state) {
    result.clear();
    fcl::collide(&pair.a, &pair.b, request, result);
    benchmark::DoNotOptimize(result.numContacts());
  }
  const cvms::PenetrationResult exact = cvms::penetration(o.a, o.b);
  const double depth = cvms::nearest_double_sqrt(exact.squared_depth);
  state.counters["fcl_contact"] = result.numContacts() > 0 ? 1 : 0;
  state.counters["exact_intersect"] = exact.intersect ? 1 : 0;
  if (result.numContacts() > 0 && exact.intersect) {
    const fcl::Contactd& c = result.getContact(0);
    state.counters["fcl_depth"] = c.penetration_depth;
    state.counters["exact_depth"] = depth;
    state.counters["rel_error"] = relative_error(c.penetration_depth, depth);
    const double dx = cvms::to_double_nearest(exact.direction.x), dy = cvms::to_double_nearest(exact.direction.y),
                 dz = cvms::to_double_nearest(exact.direction.z);
    const double norm = std::sqrt(dx * dx + dy * dy + dz * dz) * c.normal.norm();
    const double cosine = norm > 0 ? (dx * c.normal.x() + dy * c.normal.y() + dz * c.normal.z()) / norm : 0.0;
    // The exact direction may be one of several tied facets: FCL is only
    // wrong if its depth is also off.
    state.counters["direction_wrong"] = (cosine < std::cos(1e-6) && relative_error(c.penetration_depth, depth) > 1e-6) ? 1 : 0;
  }
}

void all_rows(benchmark::internal::Benchmark* b) {
  for (int pair = 0; pair < cvms_bench::kPairs; ++pair)
    for (int placement = 0; placement < 3; ++placement) b->Args({pair, placement});
}

// Third argument: the GJK solver (0 libccd, 1 FCL's own).
void distance_rows(benchmark::internal::Benchmark* b) {
  for (int solver : {static_cast<int>(fcl::GST_LIBCCD), static_cast<int>(fcl::GST_INDEP)})
    for (int pair = 0; pair < cvms_bench::kPairs; ++pair)
      for (int placement = 0; placement < 3; ++placement) b->Args({pair, placement, solver});
}

BENCHMARK(BM_FclDistance)->Apply(distance_rows)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FclPenetration)->Apply(all_rows)->Unit(benchmark::kMicrosecond);

}  // namespace
