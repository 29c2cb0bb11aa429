// SPDX-License-Identifier: MIT
// The exact fingerprints and the summary line of allocation_sweep.hpp.
#include "support/allocation_sweep.hpp"

#include <sstream>

#include "cvms/rational.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define CVMS_SWEEP_LEAK_CHECK 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CVMS_SWEEP_LEAK_CHECK 1
#endif
#endif
#ifdef CVMS_SWEEP_LEAK_CHECK
#include <sanitizer/lsan_interface.h>
#endif

namespace cvms::test {
namespace {

void put(std::ostream& out, const Vec3& v) {
  out << to_string(v.x) << ' ' << to_string(v.y) << ' ' << to_string(v.z);
}

void put(std::ostream& out, const HalfspaceRow& row) {
  put(out, row.normal);
  out << " <= " << to_string(row.offset) << '\n';
}

}  // namespace

std::string fingerprint(const PolygonSoup& soup) {
  std::ostringstream out;
  out << soup.points.size() << " points\n";
  for (const Vec3& p : soup.points) {
    put(out, p);
    out << '\n';
  }
  out << soup.num_faces() << " faces\n";
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    for (const std::uint32_t i : soup.face(f)) out << i << ' ';
    out << '\n';
  }
  return out.str();
}

std::string fingerprint(const ConvexPolyhedron& p) {
  std::ostringstream out;
  out << fingerprint(p.to_soup());
  for (std::uint32_t f = 0; f < p.num_facets(); ++f) {
    put(out, p.normal(FaceId(f)));
    out << " . x = " << to_string(p.plane_offset(FaceId(f))) << '\n';
  }
  return out.str();
}

std::string fingerprint(const ConvexSet& s) {
  std::ostringstream out;
  out << "dimension " << s.dimension() << '\n';
  if (s.dimension() == 3) return out.str() + fingerprint(s.polyhedron());
  out << fingerprint(s.vertices());
  if (s.dimension() == 2) {
    put(out, s.normal());
    out << " . x = " << to_string(s.plane_offset()) << '\n';
  }
  return out.str();
}

std::string fingerprint(const ConvexUnion& u) {
  std::string text = std::to_string(u.size()) + " pieces\n";
  for (const ConvexPolyhedron& piece : u.pieces()) text += fingerprint(piece);
  return text;
}

std::string fingerprint(const Solid& s) {
  std::ostringstream out;
  out << "volume " << to_string(s.volume()) << ", shells " << s.num_shells() << ", cavities "
      << s.num_cavities() << ", genus " << s.genus() << ", reflex edges " << s.num_reflex_edges() << '\n';
  out << fingerprint(s.to_soup());
  for (const auto& t : s.triangles()) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return out.str();
}

std::string fingerprint(const HalfspaceSystem& system) {
  std::ostringstream out;
  out << system.equalities.size() << " equalities\n";
  for (const HalfspaceRow& row : system.equalities) put(out, row);
  out << system.inequalities.size() << " inequalities\n";
  for (const HalfspaceRow& row : system.inequalities) put(out, row);
  return out.str();
}

std::string fingerprint(const std::vector<HalfspaceRow>& rows) {
  std::ostringstream out;
  for (const HalfspaceRow& row : rows) put(out, row);
  return out.str();
}

std::string fingerprint(const HalfspaceFile& file) {
  return "dimension " + std::to_string(file.dimension) + '\n' + fingerprint(file.system);
}

std::string fingerprint(const PointFile& file) {
  return "dimension " + std::to_string(file.dimension) + '\n' + fingerprint(file.points);
}

std::string fingerprint(const HalfspaceIntersection& intersection) {
  std::ostringstream out;
  out << fingerprint(intersection.set);
  if (intersection.unbounded_direction) {
    out << "unbounded ";
    put(out, *intersection.unbounded_direction);
  }
  return out.str();
}

std::string fingerprint(const DistanceResult& d) {
  std::ostringstream out;
  out << "squared distance " << to_string(d.squared_distance) << (d.intersect ? ", meet" : ", apart") << "\n";
  put(out, d.witness_a);
  out << '\n';
  put(out, d.witness_b);
  return out.str();
}

std::string fingerprint(const PenetrationResult& p) {
  std::ostringstream out;
  out << "squared depth " << to_string(p.squared_depth) << (p.intersect ? ", meet" : ", apart") << "\n";
  put(out, p.direction);
  out << " offset " << to_string(p.offset) << '\n';
  put(out, p.witness_a);
  out << '\n';
  put(out, p.witness_b);
  return out.str();
}

std::string fingerprint(const std::vector<Vec3>& points) {
  std::ostringstream out;
  out << points.size() << " points\n";
  for (const Vec3& p : points) {
    put(out, p);
    out << '\n';
  }
  return out.str();
}

bool unreachable_blocks() {
#ifdef CVMS_SWEEP_LEAK_CHECK
  return __lsan_do_recoverable_leak_check() != 0;
#else
  return false;
#endif
}

std::string summary(std::string_view name, const SweepReport& report) {
  std::ostringstream out;
  out << name << ": " << report.allocations << " allocations, " << report.failing_runs << " failing runs ("
      << report.bad_allocs << " std::bad_alloc, " << report.errors << " cvms::Error";
  for (const auto& [category, count] : report.error_categories) out << ' ' << category << ':' << count;
  out << ", " << report.completed << " completed)";
  return out.str();
}

}  // namespace cvms::test
