// SPDX-License-Identifier: MIT
// to_halfspaces: the minimal rows of a convex set, read off its canonical
// form (cvms/convex_set.hpp), each scaled to primitive integers.
#include <utility>

#include "cvms/halfspaces.hpp"

namespace cvms {

HalfspaceRow primitive_row(const HalfspaceRow& row) {
  const Rational* parts[4] = {&row.normal.x, &row.normal.y, &row.normal.z, &row.offset};
  mpz_class scale = 1;
  for (const Rational* p : parts) mpz_lcm(scale.get_mpz_t(), scale.get_mpz_t(), p->get_den_mpz_t());
  mpz_class common = 0;
  for (const Rational* p : parts) {
    const mpz_class n = p->get_num() * (scale / p->get_den());
    mpz_gcd(common.get_mpz_t(), common.get_mpz_t(), n.get_mpz_t());
  }
  if (common == 0) return {Vec3{0, 0, 0}, 0};
  if (is_zero(row.normal)) return {Vec3{0, 0, 0}, Rational(sgn(row.offset))};
  Rational factor(scale, common);
  factor.canonicalize();
  return {factor * row.normal, factor * row.offset};
}

namespace {

HalfspaceRow row_through(const Vec3& normal, const Vec3& point) { return primitive_row({normal, dot(normal, point)}); }

HalfspaceSystem polygon_rows(const ConvexSet& s) {
  HalfspaceSystem system;
  system.equalities.push_back(primitive_row({s.normal(), s.plane_offset()}));
  const std::vector<Vec3> v = s.vertices();
  const std::vector<Vec3> normals = s.edge_normals();
  for (std::size_t i = 0; i < v.size(); ++i) system.inequalities.push_back(row_through(normals[i], v[i]));
  return system;
}

// The line through p along e: for k the first coordinate where e is
// nonzero, the equalities e_k x_j − e_j x_k == const for the other j.
HalfspaceSystem segment_rows(const Vec3& p, const Vec3& q) {
  HalfspaceSystem system;
  const Vec3 e = q - p;
  int k = 0;
  while (sgn(e[k]) == 0) ++k;
  for (int j = 0; j < 3; ++j) {
    if (j == k) continue;
    Vec3 n{0, 0, 0};
    n[j] = e[k];
    n[k] = -e[j];
    system.equalities.push_back(row_through(n, p));
  }
  system.inequalities.push_back(row_through(e, q));
  system.inequalities.push_back(row_through(-e, p));
  return system;
}

}  // namespace

HalfspaceSystem to_halfspaces(const ConvexSet& set) {
  HalfspaceSystem system;
  switch (set.dimension()) {
    case -1:
      system.inequalities.push_back({Vec3{0, 0, 0}, -1});
      return system;
    case 0: {
      const Vec3 p = set.vertices().front();
      for (int k = 0; k < 3; ++k) {
        Vec3 n{0, 0, 0};
        n[k] = 1;
        system.equalities.push_back(row_through(n, p));
      }
      return system;
    }
    case 1: {
      const std::vector<Vec3> v = set.vertices();
      return segment_rows(v[0], v[1]);
    }
    case 2:
      return polygon_rows(set);
    default: {
      const ConvexPolyhedron& p = set.polyhedron();
      for (FaceId f : p.mesh().faces()) system.inequalities.push_back(primitive_row({p.normal(f), p.plane_offset(f)}));
      return system;
    }
  }
}

}  // namespace cvms
