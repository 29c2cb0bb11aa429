// SPDX-License-Identifier: MIT
// ConvexPolyhedron: exact convexity verification of a closed mesh, merging of
// coplanar faces into maximal facets, removal of non-extreme vertices, and the
// cached normals, plane offsets and double approximations.
//
// from_mesh works in O(V + E + F) predicates:
//  1. topology: one connected component and Euler characteristic 2 (a sphere);
//  2. every face: exact area vector N_f (its orientation normal); zero area is
//     `degenerate`; a face must be planar and a convex polygon (collinear
//     vertices allowed), else `not_convex`;
//  3. all vertices on one plane: `degenerate` (flat, zero volume);
//  4. every edge between faces f, g with halfedge h in f and direction d:
//     coplanar if N_f, N_g are parallel (same direction: merged into one
//     facet; opposite: a zero-angle fold, `not_convex`), else convex iff
//     det[N_f, N_g, d] > 0. The global orientation is the one under which the
//     majority of the non-coplanar edges are convex (a consistently inward mesh
//     has every edge reflex and is flipped); the first edge that is reflex
//     under it is reported;
//  5. merged facets (union-find over coplanar edges) must each have exactly one
//     boundary cycle, and that cycle must be a strictly convex polygon after
//     dropping the vertices where it runs straight;
//  6. a vertex is extreme iff it lies on >= 3 facets (counted as region
//     changes around its fan); extreme vertices must be corners of all their
//     facets and the others must not be;
//  7. global check, on the result: a point o inside a tetrahedron of vertices
//     must be strictly below every facet plane, and a ray from o through the
//     interior of facet 0 must meet no other (closed) facet.
//
// Why 1-7 prove that the result bounds a convex polytope: by (7) every facet
// is seen from o from its inner side, so the central projection from o onto a
// sphere around o is orientation preserving on every facet; across an edge the
// two facets then project to opposite sides of the edge's image, so the
// projection is a branched covering of the sphere by the (connected, closed)
// surface, and its degree is the number of preimages of the regular direction
// of the ray: exactly 1. A covering of degree 1 is a homeomorphism, so the
// surface is star-shaped from o and bounds a closed star-shaped body K. Near a
// vertex v the surface is then the graph (over a plane transversal to o - v) of
// a piecewise-linear, positively homogeneous function that is concave across
// every ray (the edges are convex, step 4) and hence, by continuity along lines
// through v approximated by lines avoiding v, concave: K is locally convex at
// every point, and a connected closed locally convex set is convex
// (Tietze-Nakajima). Inside a facet, the input faces are convex polygons with
// the facet's orientation and the facet boundary winds once, so they tile the
// facet exactly (degree argument in the plane): the input surface is the
// surface of the result.
#include "cvms/convex_polyhedron.hpp"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>
#include <utility>

#include "angular_order.hpp"
#include "cvms/error.hpp"
#include "dyadic.hpp"
#include "element_names.hpp"
#include "filtered_predicates.hpp"
#include "no_index.hpp"
#include "polyhedron_builder.hpp"

namespace cvms {
namespace {

using detail::no_index;
using detail::edge_name;
using detail::str;

[[noreturn]] void not_convex(const std::string& message) { throw Error(ErrorCategory::not_convex, message); }

// Outcome of checking a closed planar polygon for strict convexity.
enum class PolygonFault { none, right_turn, reversal, too_few_corners, winds_more_than_once };

struct PolygonCheck {
  PolygonFault fault = PolygonFault::none;
  std::size_t at = 0;        // polygon position of the fault
  std::vector<char> corner;  // per position: strict left turn (1) or straight (0)
};

// Checks that p[0..m) (m >= 3, consecutive points distinct) is, seen from the
// side n points to, a strictly convex counterclockwise polygon once the
// vertices where it runs straight on are dropped. All turns must be left or
// straight on; then the polygon is convex iff its corners' edge directions turn
// around exactly once, i.e. (every turn being in (0, pi)) iff their angles,
// measured counterclockwise from the first corner edge, descend exactly once.
PolygonCheck check_convex_polygon(const std::vector<const Vec3*>& p, const Vec3& n) {
  const std::size_t m = p.size();
  PolygonCheck r;
  r.corner.assign(m, 0);
  std::vector<std::size_t> corners;
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& prev = *p[(i + m - 1) % m];
    const Vec3& next = *p[(i + 1) % m];
    const Vec3 a = *p[i] - prev, b = next - *p[i];
    const Sign s = sign_triple(n, a, b);
    if (s == Sign::negative) return {PolygonFault::right_turn, i, {}};
    if (s == Sign::zero) {
      if (sign_dot(a, b) != Sign::positive) return {PolygonFault::reversal, i, {}};
    } else {
      r.corner[i] = 1;
      corners.push_back(i);
    }
  }
  const std::size_t k = corners.size();
  if (k < 3) return {PolygonFault::too_few_corners, 0, {}};
  std::vector<Vec3> e(k);
  for (std::size_t j = 0; j < k; ++j) e[j] = *p[corners[(j + 1) % k]] - *p[corners[j]];
  const Vec3& ref = e[0];
  // Angles about n from ref (lib/predicates/angular_order.hpp).
  auto half = [&](const Vec3& v) {
    return detail::half_turn(sign_triple(n, ref, v), [&] { return sign_dot(ref, v); });
  };
  auto angle_less = [&](const Vec3& a, const Vec3& b) {
    return detail::compare_angle(half(a), half(b), [&] { return sign_triple(n, a, b); }) == Sign::negative;
  };
  std::size_t descents = 0;
  for (std::size_t j = 0; j < k; ++j)
    if (angle_less(e[(j + 1) % k], e[j])) ++descents;
  if (descents != 1) return {PolygonFault::winds_more_than_once, 0, {}};
  return r;
}

std::string describe_fault(const PolygonCheck& c, const std::vector<std::uint32_t>& vertex_ids) {
  switch (c.fault) {
    case PolygonFault::right_turn: return "has a reflex corner at vertex " + str(vertex_ids[c.at]);
    case PolygonFault::reversal: return "turns back on itself at vertex " + str(vertex_ids[c.at]);
    case PolygonFault::too_few_corners: return "has fewer than 3 corners";
    case PolygonFault::winds_more_than_once: return "winds around more than once (self-intersecting)";
    case PolygonFault::none: break;
  }
  return "";
}

// The orientation normal (twice the vector area) of a planar polygon.
Vec3 area_vector(const std::vector<const Vec3*>& p) {
  Vec3 n{0, 0, 0};
  for (std::size_t i = 1; i + 1 < p.size(); ++i) n += cross(*p[i] - *p[0], *p[i + 1] - *p[0]);
  return n;
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::uint32_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

enum class EdgeKind : unsigned char { coplanar, fold, convex, reflex };

// 1. Topology: connected and a sphere.
void check_sphere(const Mesh& mesh) {
  const std::uint32_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  UnionFind components(nf);
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = Mesh::halfedge(e);
    components.unite(mesh.face(h).index(), mesh.face(Mesh::twin(h)).index());
  }
  std::uint32_t count = 0;
  for (std::uint32_t f = 0; f < nf; ++f) count += components.find(f) == f;
  if (count != 1)
    throw Error(ErrorCategory::topology,
                "the surface has " + str(count) + " connected components (a convex polyhedron has one)");
  const long long chi = static_cast<long long>(nv) - mesh.num_edges() + nf;
  if (chi != 2)
    throw Error(ErrorCategory::topology, "the surface has Euler characteristic " + std::to_string(chi) +
                                             " (genus " + std::to_string((2 - chi) / 2) +
                                             "); a convex polyhedron is a sphere (2)");
}

// The orientation normal of face f with corners pts (vertex indices ids),
// once the face is known to have nonzero area and, beyond triangles, to be
// planar and a convex polygon.
Vec3 checked_face_normal(FaceId f, const std::vector<const Vec3*>& pts,
                         const std::vector<std::uint32_t>& ids) {
  Vec3 n = area_vector(pts);
  if (is_zero(n)) {
    bool collinear = true;
    for (std::size_t i = 2; i < pts.size() && collinear; ++i)
      collinear = is_parallel(*pts[1] - *pts[0], *pts[i] - *pts[0]);
    if (collinear)
      throw Error(ErrorCategory::degenerate,
                  "face " + str(f.index()) + " has zero area (its vertices are collinear)");
    not_convex("face " + str(f.index()) + " has zero signed area (it is not a convex polygon)");
  }
  if (pts.size() > 3) {
    for (std::size_t i = 1; i < pts.size(); ++i)
      if (sign_dot(n, *pts[i] - *pts[0]) != Sign::zero)
        not_convex("face " + str(f.index()) + " is not planar (vertex " + str(ids[i]) +
                   " is off the plane of the others)");
    PolygonCheck c = check_convex_polygon(pts, n);
    if (c.fault != PolygonFault::none)
      not_convex("face " + str(f.index()) + " is not a convex polygon: it " + describe_fault(c, ids));
  }
  return n;
}

// 2. Faces: orientation normal, zero area, planarity, convexity.
std::vector<Vec3> face_normals(const Mesh& mesh) {
  std::vector<Vec3> face_normal(mesh.num_faces());
  std::vector<const Vec3*> pts;
  std::vector<std::uint32_t> ids;
  for (FaceId f : mesh.faces()) {
    pts.clear();
    ids.clear();
    for (HalfedgeId h : mesh.face_halfedges(f)) {
      pts.push_back(&mesh.position(mesh.from(h)));
      ids.push_back(mesh.from(h).index());
    }
    face_normal[f.index()] = checked_face_normal(f, pts, ids);
  }
  return face_normal;
}

// 3. Flat: every vertex on the plane of face 0 (normal n).
void check_not_flat(const Mesh& mesh, const Vec3& n) {
  const Vec3& p0 = mesh.position(mesh.from(mesh.halfedge(FaceId(0))));
  bool flat = true;
  for (VertexId v : mesh.vertices())
    if (sign_dot(n, mesh.position(v) - p0) != Sign::zero) {
      flat = false;
      break;
    }
  if (flat)
    throw Error(ErrorCategory::degenerate, "flat polyhedron: all vertices are coplanar (zero volume)");
}

// What step 4 finds: the faces joined by coplanar edges, and whether the
// mesh is consistently inward (then flipped).
struct EdgeClasses {
  UnionFind coplanar;
  bool flip;
};

// 4. Edges.
EdgeClasses classify_edges(const Mesh& mesh, const std::vector<Vec3>& face_normal) {
  std::vector<EdgeKind> kind(mesh.num_edges());
  std::size_t num_convex = 0, num_reflex = 0;
  EdgeClasses out{UnionFind(mesh.num_faces()), false};
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = Mesh::halfedge(e);
    const std::uint32_t f = mesh.face(h).index(), g = mesh.face(Mesh::twin(h)).index();
    const Vec3& n_f = face_normal[f];
    const Vec3& n_g = face_normal[g];
    EdgeKind k;
    if (is_parallel(n_f, n_g)) {
      k = sign_dot(n_f, n_g) == Sign::positive ? EdgeKind::coplanar : EdgeKind::fold;
    } else {
      const Vec3 d = mesh.position(mesh.to(h)) - mesh.position(mesh.from(h));
      k = sign_triple(n_f, n_g, d) == Sign::positive ? EdgeKind::convex : EdgeKind::reflex;
    }
    kind[e.index()] = k;
    if (k == EdgeKind::coplanar) out.coplanar.unite(f, g);
    if (k == EdgeKind::fold)
      not_convex(edge_name(mesh.from(h).index(), mesh.to(h).index()) + ": faces " + str(f) + " and " + str(g) +
                 " fold back onto each other (zero dihedral angle)");
    num_convex += k == EdgeKind::convex;
    num_reflex += k == EdgeKind::reflex;
  }
  out.flip = num_reflex > num_convex;
  const EdgeKind wrong = out.flip ? EdgeKind::convex : EdgeKind::reflex;
  for (EdgeId e : mesh.edges())
    if (kind[e.index()] == wrong) {
      const HalfedgeId h = Mesh::halfedge(e);
      not_convex("reflex " + edge_name(mesh.from(h).index(), mesh.to(h).index()) + " between faces " +
                 str(mesh.face(h).index()) + " and " + str(mesh.face(Mesh::twin(h)).index()));
    }
  return out;
}

// 5. Regions (merged facets), numbered by their smallest face.
struct Regions {
  const Mesh& mesh;
  std::vector<std::uint32_t> of_face;     // the region of each face
  std::vector<std::uint32_t> first_face;  // the smallest face of each region

  Regions(const Mesh& m, UnionFind& coplanar) : mesh(m), of_face(m.num_faces()) {
    std::vector<std::uint32_t> id_of_root(m.num_faces(), no_index);
    for (std::uint32_t f = 0; f < m.num_faces(); ++f) {
      const std::uint32_t r = coplanar.find(f);
      if (id_of_root[r] == no_index) {
        id_of_root[r] = static_cast<std::uint32_t>(first_face.size());
        first_face.push_back(f);
      }
      of_face[f] = id_of_root[r];
    }
  }
  [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(first_face.size()); }
  [[nodiscard]] std::uint32_t of(HalfedgeId h) const { return of_face[mesh.face(h).index()]; }
  [[nodiscard]] bool is_border(HalfedgeId h) const { return of(h) != of(Mesh::twin(h)); }
  [[nodiscard]] std::string facet_name(std::uint32_t r) const {
    return "the facet containing face " + str(first_face[r]);
  }
};

// Boundary cycles: from a border halfedge h, the next border halfedge of the
// same region leaves to(h); rotate clockwise around to(h) through the
// region's faces until the face across is outside the region.
std::vector<std::vector<HalfedgeId>> boundary_cycles(const Regions& regions) {
  const Mesh& mesh = regions.mesh;
  const std::uint32_t nh = mesh.num_halfedges();
  std::vector<std::vector<HalfedgeId>> cycle(regions.size());
  std::vector<char> visited(nh, 0);
  for (HalfedgeId start : mesh.halfedges()) {
    if (visited[start.index()] || !regions.is_border(start)) continue;
    const std::uint32_t r = regions.of(start);
    if (!cycle[r].empty())
      not_convex(regions.facet_name(r) +
                 " (coplanar faces merged) has more than one boundary cycle (a hole)");
    HalfedgeId h = start;
    std::uint32_t steps = 0;
    do {
      visited[h.index()] = 1;
      cycle[r].push_back(h);
      HalfedgeId n = mesh.next(h);
      while (!regions.is_border(n) && ++steps <= nh) n = mesh.next(Mesh::twin(n));
      h = n;
    } while (h != start && ++steps <= 2 * nh);
    if (h != start) throw Error(ErrorCategory::topology, "corrupt mesh: a facet boundary does not close");
  }
  for (std::uint32_t r = 0; r < regions.size(); ++r)
    if (cycle[r].size() < 3) not_convex(regions.facet_name(r) + " has no proper boundary");
  return cycle;
}

// 6. Extreme vertices: on >= 3 facets.
struct FacetsAtVertices {
  std::vector<std::uint32_t> count;
  [[nodiscard]] bool extreme(std::uint32_t v) const { return count[v] >= 3; }
};

FacetsAtVertices facets_at_vertices(const Regions& regions) {
  FacetsAtVertices facets_at{std::vector<std::uint32_t>(regions.mesh.num_vertices(), 0)};
  for (HalfedgeId h : regions.mesh.halfedges())
    if (regions.is_border(h)) ++facets_at.count[regions.mesh.from(h).index()];
  return facets_at;
}

// Facet polygons, and corners agree with extremality.
std::vector<std::vector<std::uint32_t>> facet_corners(const Regions& regions,
                                                      const std::vector<std::vector<HalfedgeId>>& cycle,
                                                      const std::vector<Vec3>& face_normal,
                                                      const FacetsAtVertices& facets_at) {
  const Mesh& mesh = regions.mesh;
  std::vector<std::vector<std::uint32_t>> corners(regions.size());
  std::vector<const Vec3*> pts;
  std::vector<std::uint32_t> ids;
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    pts.clear();
    ids.clear();
    for (HalfedgeId h : cycle[r]) {
      pts.push_back(&mesh.position(mesh.from(h)));
      ids.push_back(mesh.from(h).index());
    }
    PolygonCheck c = check_convex_polygon(pts, face_normal[regions.first_face[r]]);
    if (c.fault != PolygonFault::none)
      not_convex(regions.facet_name(r) + " (coplanar faces merged) is not a convex polygon: it " +
                 describe_fault(c, ids));
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (c.corner[i] != 0 && !facets_at.extreme(ids[i]))
        not_convex("vertex " + str(ids[i]) + " is a corner of " + regions.facet_name(r) +
                   " but lies on only " + str(facets_at.count[ids[i]]) + " facets");
      if (c.corner[i] == 0 && facets_at.extreme(ids[i]))
        not_convex("vertex " + str(ids[i]) + " lies on " + str(facets_at.count[ids[i]]) +
                   " facets but on a straight side of " + regions.facet_name(r));
      if (c.corner[i] != 0) corners[r].push_back(ids[i]);
    }
  }
  return corners;
}

// 7. The result: extreme vertices in input order, facets ordered by their
// smallest input face, each starting at its smallest vertex index.
Mesh merged_mesh(const Mesh& mesh, const std::vector<std::vector<std::uint32_t>>& facet_corners,
                 const FacetsAtVertices& facets_at, bool flip) {
  PolygonSoup out;
  std::vector<std::uint32_t> new_index(mesh.num_vertices(), no_index);
  for (std::uint32_t v = 0; v < mesh.num_vertices(); ++v)
    if (facets_at.extreme(v)) {
      new_index[v] = static_cast<std::uint32_t>(out.points.size());
      out.points.push_back(mesh.position(VertexId(v)));
    }
  std::vector<std::uint32_t> facet;
  for (const std::vector<std::uint32_t>& corners : facet_corners) {
    facet.clear();
    for (std::uint32_t v : corners) facet.push_back(new_index[v]);
    if (flip) std::reverse(facet.begin(), facet.end());
    std::rotate(facet.begin(), std::min_element(facet.begin(), facet.end()), facet.end());
    out.add_face(facet);
  }
  Mesh merged;
  try {
    merged = Mesh::from_soup(std::move(out));
  } catch (const Error& e) {
    not_convex(std::string("the merged facets do not form a closed surface: ") + e.what());
  }
  return merged;
}

// 8. Global: an interior point o below every facet, and a ray from o that
// crosses facet 0 only. The facets of p are the regions, in order.
void check_global(const ConvexPolyhedron& p, const Regions& regions) {
  const Mesh& m = p.mesh();
  const HalfedgeId h0 = m.halfedge(FaceId(0));
  const Vec3& a = m.position(m.from(h0));
  const Vec3& b = m.position(m.to(h0));
  const Vec3& c = m.position(m.to(m.next(h0)));
  const Vec3* w = nullptr;
  for (VertexId v : m.vertices())
    if (side_of_plane(m.position(v), p.normal(FaceId(0)), p.plane_offset(FaceId(0))) == Sign::negative) {
      w = &m.position(v);
      break;
    }
  if (w == nullptr) not_convex(regions.facet_name(0) + " has every vertex on its plane");
  const Vec3 o = Rational(1, 4) * (a + b + c + *w);
  const Vec3 dir = (a + b + c) - Rational(3) * *w;  // from o through (a + b + c) / 3
  for (FaceId f : m.faces()) {
    if (side_of_plane(o, p.normal(f), p.plane_offset(f)) != Sign::negative)
      not_convex("the surface is locally convex but not convex: an interior point lies above " +
                 regions.facet_name(f.index()));
  }
  for (FaceId f : m.faces()) {
    if (f.index() == 0 || sign_dot(p.normal(f), dir) != Sign::positive) continue;
    bool hit = true;
    for (HalfedgeId h : m.face_halfedges(f))
      if (sign_triple(m.position(m.from(h)) - o, m.position(m.to(h)) - o, dir) == Sign::negative) {
        hit = false;
        break;
      }
    if (hit)
      not_convex("the surface is locally convex but winds around its interior more than once (" +
                 regions.facet_name(0) + " and " + regions.facet_name(f.index()) +
                 " overlap as seen from inside)");
  }
}

}  // namespace

Vec3 primitive_direction(const Vec3& v) {
  if (is_zero(v)) throw Error(ErrorCategory::invalid_argument, "primitive_direction of the zero vector");
  mpz_class l = 1;
  for (int i = 0; i < 3; ++i) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), v[i].get_den_mpz_t());
  mpz_class c[3];
  mpz_class g = 0;
  for (int i = 0; i < 3; ++i) {
    c[i] = v[i].get_num() * (l / v[i].get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c[i].get_mpz_t());
  }
  return {Rational(c[0] / g), Rational(c[1] / g), Rational(c[2] / g)};
}

Vec3 ConvexPolyhedron::edge_vector(HalfedgeId h) const {
  return detail::subtract(vertex(mesh_.to(h)), vertex(mesh_.from(h)));
}

ConvexPolyhedron ConvexPolyhedron::from_soup(PolygonSoup soup) { return from_mesh(Mesh::from_soup(std::move(soup))); }

ConvexPolyhedron::ConvexPolyhedron() = default;
ConvexPolyhedron::~ConvexPolyhedron() = default;
ConvexPolyhedron::ConvexPolyhedron(const ConvexPolyhedron&) = default;
ConvexPolyhedron::ConvexPolyhedron(ConvexPolyhedron&&) noexcept = default;
ConvexPolyhedron& ConvexPolyhedron::operator=(const ConvexPolyhedron&) = default;
ConvexPolyhedron& ConvexPolyhedron::operator=(ConvexPolyhedron&&) noexcept = default;

ConvexPolyhedron::ConvexPolyhedron(detail::PolyhedronParts&& parts)
    : mesh_(std::move(parts.mesh)),
      normals_(std::move(parts.normals)),
      offsets_(std::move(parts.offsets)),
      approx_(std::make_shared<const detail::PolyhedronApproximations>(std::move(parts.approx))) {}

ConvexPolyhedron ConvexPolyhedron::from_mesh(const Mesh& mesh) {
  if (mesh.num_faces() == 0 || mesh.num_vertices() == 0) throw Error(ErrorCategory::topology, "empty mesh");
  // Steps 1-6 check the input, step 7 builds the result and step 8 checks it
  // globally (the file comment says why that suffices).
  check_sphere(mesh);
  const std::vector<Vec3> face_normal = face_normals(mesh);
  check_not_flat(mesh, face_normal[0]);
  EdgeClasses edges = classify_edges(mesh, face_normal);
  const Regions regions(mesh, edges.coplanar);
  const std::vector<std::vector<HalfedgeId>> cycles = boundary_cycles(regions);
  const FacetsAtVertices facets_at = facets_at_vertices(regions);
  const std::vector<std::vector<std::uint32_t>> corners =
      facet_corners(regions, cycles, face_normal, facets_at);
  ConvexPolyhedron p(detail::parts_with_planes(merged_mesh(mesh, corners, facets_at, edges.flip)));
  check_global(p, regions);
  return p;
}

bool ConvexPolyhedron::is_convex() const {
  const Mesh& m = mesh_;
  try {
    m.validate();
  } catch (const Error&) {
    return false;
  }
  if (euler_characteristic() != 2) return false;
  if (!approx_ || approx_->vertices.size() != m.num_vertices() || normals_.size() != m.num_faces() ||
      approx_->normals.size() != m.num_faces() || offsets_.size() != m.num_faces())
    return false;
  std::vector<const Vec3*> pts;
  for (FaceId f : m.faces()) {
    pts.clear();
    for (HalfedgeId h : m.face_halfedges(f)) pts.push_back(&m.position(m.from(h)));
    const Vec3 n = cross(*pts[1] - *pts[0], *pts[2] - *pts[1]);
    if (is_zero(n) || primitive_direction(n) != normals_[f.index()]) return false;
    if (dot(normals_[f.index()], *pts[0]) != offsets_[f.index()]) return false;
    for (const Vec3* q : pts)
      if (side_of_plane(*q, normals_[f.index()], offsets_[f.index()]) != Sign::zero) return false;
    PolygonCheck c = check_convex_polygon(pts, n);
    if (c.fault != PolygonFault::none) return false;
    if (std::count(c.corner.begin(), c.corner.end(), 1) != static_cast<std::ptrdiff_t>(pts.size())) return false;
  }
  for (VertexId v : m.vertices()) {
    std::uint32_t on = 0;
    for (FaceId f : m.faces()) {
      const Sign s = side_of_plane(m.position(v), normals_[f.index()], offsets_[f.index()]);
      if (s == Sign::positive) return false;
      on += s == Sign::zero;
    }
    if (on < 3) return false;
  }
  // Distinct planes: with every vertex on or below every plane, two facets
  // with equal normals would lie in one plane (covering it twice).
  std::set<Vec3> distinct(normals_.begin(), normals_.end());
  if (distinct.size() != normals_.size()) return false;
  for (VertexId v : m.vertices()) {
    const ApproxVec3 a = ApproxVec3::of(m.position(v));
    const ApproxVec3& b = approx_->vertices[v.index()];
    if (a.x.value != b.x.value || a.y.value != b.y.value || a.z.value != b.z.value) return false;
  }
  return true;
}

int ConvexPolyhedron::euler_characteristic() const noexcept {
  return static_cast<int>(num_vertices()) - static_cast<int>(num_edges()) + static_cast<int>(num_facets());
}

ConvexPolyhedron ConvexPolyhedron::transformed(const Mat3& linear, const Vec3& offset) const {
  const Vec3 r0{linear.m[0][0], linear.m[0][1], linear.m[0][2]};
  const Vec3 r1{linear.m[1][0], linear.m[1][1], linear.m[1][2]};
  const Vec3 r2{linear.m[2][0], linear.m[2][1], linear.m[2][2]};
  const Sign det = sign_triple(r0, r1, r2);
  if (det == Sign::zero) throw Error(ErrorCategory::invalid_argument, "transformed: singular linear map");
  std::vector<Vec3> pts;
  pts.reserve(num_vertices());
  for (VertexId v : mesh_.vertices()) {
    pts.push_back(linear * vertex(v) + offset);
    for (int i = 0; i < 3; ++i) pts.back()[i].canonicalize();  // in case the caller's matrix was not
  }
  if (det == Sign::positive) return ConvexPolyhedron(detail::parts_with_planes(mesh_.with_positions(std::move(pts))));
  // Orientation reversing: reverse every facet so it stays counterclockwise
  // seen from outside.
  PolygonSoup soup = mesh_.to_soup();
  soup.points = std::move(pts);
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    std::reverse(soup.face_indices.begin() + soup.face_offsets[f], soup.face_indices.begin() + soup.face_offsets[f + 1]);
  return detail::trusted_polyhedron(std::move(soup));
}

ConvexPolyhedron ConvexPolyhedron::translated(const Vec3& offset) const {
  std::vector<Vec3> pts;
  pts.reserve(num_vertices());
  for (VertexId v : mesh_.vertices()) {
    pts.push_back(vertex(v) + offset);
    for (int i = 0; i < 3; ++i) pts.back()[i].canonicalize();
  }
  if (!approx_) return {};
  detail::PolyhedronParts p;
  p.mesh = mesh_.with_positions(std::move(pts));
  p.approx.vertices.reserve(num_vertices());
  for (VertexId v : p.mesh.vertices()) p.approx.vertices.push_back(ApproxVec3::of(p.mesh.position(v)));
  p.normals = normals_;
  p.approx.normals = approx_->normals;
  p.offsets.reserve(offsets_.size());
  for (FaceId f : mesh_.faces()) {
    p.offsets.push_back(offsets_[f.index()] + dot(normals_[f.index()], offset));
    p.offsets.back().canonicalize();
  }
  return ConvexPolyhedron(std::move(p));
}

ConvexPolyhedron ConvexPolyhedron::reflected() const {
  Mat3 minus;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) minus.m[i][j] = (i == j) ? -1 : 0;
  return transformed(minus, Vec3{0, 0, 0});
}

}  // namespace cvms
