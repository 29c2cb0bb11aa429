// SPDX-License-Identifier: MIT
// ConvexPolyhedron from trusted facets with known normals (see the header).
#include "trusted_polyhedron.hpp"

#include <string>
#include <utility>

#include "cvms/error.hpp"

namespace cvms::detail {
namespace {

// dot(n, p) for an integer vector n and a rational point p, in integers:
// with L the lcm of p's denominators, dot = (sum n_i num_i (L / den_i)) / L,
// canonicalised once (one gcd) instead of after each of five rational
// operations.
Rational integer_dot(const Vec3& n, const Vec3& p, mpz_class& l, mpz_class& sum, mpz_class& term) {
  l = p.x.get_den();
  for (int i = 1; i < 3; ++i)
    if (p[i].get_den() != l) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
  sum = 0;
  for (int i = 0; i < 3; ++i) {
    if (mpz_sgn(n[i].get_num_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
    mpz_divexact(term.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
    term *= p[i].get_num();
    mpz_addmul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
  }
  Rational r(sum, l);
  r.canonicalize();
  return r;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedronAccess::from_trusted_soup(PolygonSoup soup, std::vector<Vec3> normals) {
  if (normals.size() != soup.num_faces())
    throw Error(ErrorCategory::invalid_argument, "from_trusted_soup: " + std::to_string(normals.size()) +
                                                     " normals for " + std::to_string(soup.num_faces()) +
                                                     " faces");
  ConvexPolyhedron p;
  p.mesh_ = Mesh::from_soup_with_distinct_points(std::move(soup));
  const Mesh& m = p.mesh_;
  p.vertex_approx_.reserve(m.num_vertices());
  for (VertexId v : m.vertices()) p.vertex_approx_.push_back(ApproxVec3::of(m.position(v)));
  p.normal_approx_.reserve(m.num_faces());
  p.offsets_.reserve(m.num_faces());
  mpz_class l, sum, term;
  for (FaceId f : m.faces()) {
    const Vec3& n = normals[f.index()];
    p.offsets_.push_back(integer_dot(n, m.position(m.from(m.halfedge(f))), l, sum, term));
    p.normal_approx_.push_back(ApproxVec3::of(n));
  }
  p.normals_ = std::move(normals);
  return p;
}

}  // namespace cvms::detail
