// SPDX-License-Identifier: MIT
// Written independently of the library's algorithms: plain rational
// arithmetic on the mesh data, no predicates.
#include "support/minkowski_check.hpp"

#include <set>
#include <sstream>
#include <vector>

namespace cvms::test {
namespace {

std::vector<Vec3> edge_vectors(const ConvexPolyhedron& p) {
  std::vector<Vec3> out;
  const Mesh& m = p.mesh();
  for (EdgeId e : m.edges()) {
    const HalfedgeId h = Mesh::halfedge(e);
    out.push_back(p.vertex(m.to(h)) - p.vertex(m.from(h)));
  }
  return out;
}

// How many facets of p have a normal that no facet of q has: the corner
// facets of q + p.
std::uint64_t normals_missing_from(const ConvexPolyhedron& p, const ConvexPolyhedron& q) {
  std::set<Vec3> normals_q;
  for (const Plane& pl : describe(q).planes) normals_q.insert(pl.normal);
  std::uint64_t n = 0;
  for (const Plane& pl : describe(p).planes) n += normals_q.count(pl.normal) == 0;
  return n;
}

}  // namespace

std::string check_facet_origins(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Shape& sum) {
  std::set<Vec3> normals;
  for (const Plane& p : describe(a).planes) normals.insert(p.normal);
  for (const Plane& p : describe(b).planes) normals.insert(p.normal);
  const std::vector<Vec3> ea = edge_vectors(a);
  const std::vector<Vec3> eb = edge_vectors(b);
  for (const Plane& p : sum.planes) {
    if (normals.count(p.normal)) continue;
    std::vector<const Vec3*> pa;
    std::vector<const Vec3*> pb;
    for (const Vec3& e : ea)
      if (sgn(dot(e, p.normal)) == 0) pa.push_back(&e);
    for (const Vec3& e : eb)
      if (sgn(dot(e, p.normal)) == 0) pb.push_back(&e);
    bool found = false;
    for (const Vec3* x : pa) {
      for (const Vec3* y : pb) {
        if (!is_zero(cross(*x, *y))) {
          found = true;
          break;
        }
      }
      if (found) break;
    }
    if (!found)
      return "facet normal " + to_text(p.normal) + " is no facet normal of A or B and no edge cross product";
  }
  return "";
}

Shape chms_shape(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  Options o;
  o.algorithm = Algorithm::chms;
  return describe(minkowski_sum(a, b, o).polyhedron);
}

std::string check_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Shape& expected,
                      const Options& options, bool check_origins, const SumFunction& sum) {
  auto run = [&](const ConvexPolyhedron& x, const ConvexPolyhedron& y) {
    return sum ? sum(x, y) : minkowski_sum(x, y, options);
  };
  std::ostringstream out;
  const MinkowskiResult ab = run(a, b);
  const MinkowskiResult ba = run(b, a);
  for (const MinkowskiResult* r : {&ab, &ba}) {
    const char* name = r == &ab ? "A+B" : "B+A";
    const std::string inv = check_invariants(r->polyhedron);
    if (!inv.empty()) {
      out << name << ": invariant broken: " << inv << "\n";
      continue;
    }
    const Shape got = describe(r->polyhedron);
    if (!(got == expected)) out << name << " differs from the oracle: " << difference(expected, got);
    const std::uint64_t f = r->polyhedron.num_facets();
    const std::uint64_t bound =
        std::uint64_t{a.num_facets()} + b.num_facets() + std::uint64_t{a.num_edges()} * b.num_edges();
    if (f > bound) out << name << ": F = " << f << " exceeds f_A + f_B + e_A e_B = " << bound << "\n";
    if (options.algorithm == Algorithm::cvms || options.algorithm == Algorithm::essdms) {
      const Stats& s = r->stats;
      const std::uint64_t first = r == &ab ? a.num_facets() : b.num_facets();
      const std::uint64_t corners = r == &ab ? normals_missing_from(b, a) : normals_missing_from(a, b);
      if (s.translated_facets + s.corner_facets + s.edge_facets != f)
        out << name << ": stats " << s.translated_facets << " + " << s.corner_facets << " + " << s.edge_facets
            << " do not add up to F = " << f << "\n";
      if (s.translated_facets != first)
        out << name << ": translated facets " << s.translated_facets << " != f_A\n";
      if (s.corner_facets != corners)
        out << name << ": corner facets " << s.corner_facets << " != " << corners
            << " (facets of B with a normal no facet of A has)\n";
      // Stats' deprecated copies of the diagnostics, which stay filled while
      // they are part of the API (the sum function may be the caller's).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
      if (s.predicate_exact + s.predicate_filtered == 0) out << name << ": no predicate calls counted\n";
#pragma GCC diagnostic pop
    }
  }
  if (out.str().empty() && check_origins) {
    const std::string o = check_facet_origins(a, b, expected);
    if (!o.empty()) out << o << "\n";
  }
  return out.str();
}

}  // namespace cvms::test
