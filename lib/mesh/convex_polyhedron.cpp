// SPDX-License-Identifier: MIT
// ConvexPolyhedron: exact convexity verification of a closed mesh, merging of
// coplanar faces into maximal facets, removal of non-extreme vertices; the
// facet planes are made when first asked for (facet_planes.hpp).
//
// from_mesh works in O(V + E + F) predicates:
//  1. topology: one connected component and Euler characteristic 2 (a sphere);
//  2. every face: zero area is `degenerate`; a face must be planar and a
//     convex polygon (collinear vertices allowed), else `not_convex`. A face
//     that passes keeps a plane triple: three of its vertices, not collinear,
//     that turn like it (found in O(degree): check_face), so that
//     orient3d against them signs a point's side of the face's plane by the
//     face's orientation normal N_f (its area vector, up to a positive
//     factor); only a failing face has its N_f computed, to report its fault
//     as stated;
//  3. all vertices on one plane: `degenerate` (flat, zero volume);
//  4. every edge between faces f, g with halfedge h in f and direction d:
//     coplanar if N_f, N_g are parallel (same direction: merged into one
//     facet; opposite: a zero-angle fold, `not_convex`), else convex iff
//     det[N_f, N_g, d] > 0, decided as the side of g's vertices against f's
//     plane (the argument is at classify_edges). The global orientation is the
//     one under which the majority of the non-coplanar edges are convex (a
//     consistently inward mesh has every edge reflex and is flipped); the first
//     edge that is reflex under it is reported;
//  5. merged facets (union-find over coplanar edges) must each have exactly one
//     boundary cycle, and that cycle must be a strictly convex polygon after
//     dropping the vertices where it runs straight;
//  6. a vertex is extreme iff it lies on >= 3 facets (counted as region
//     changes around its fan); extreme vertices must be corners of all their
//     facets and the others must not be;
//  7. global check, on the result: a point o inside a tetrahedron of vertices
//     must be strictly below every facet plane, and a ray from o through the
//     interior of facet 0 must meet no other (closed) facet.
// Primitive normals are made only where a sign needs more than orientations
// of vertices (FaceNormals): none for a triangulated surface in general
// position.
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
#include <array>
#include <deque>
#include <numeric>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>

#include "convex_polygon.hpp"
#include "cvms/error.hpp"
#include "dyadic.hpp"
#include "element_names.hpp"
#include "facet_planes.hpp"
#include "filtered_predicates.hpp"
#include "limb_arena.hpp"
#include "no_index.hpp"
#include "plane_filter.hpp"
#include "polyhedron_builder.hpp"

namespace cvms {
namespace {

using detail::edge_name;
using detail::first_corners;
using detail::no_index;
using detail::str;

[[noreturn]] void not_convex(const std::string& message) { throw Error(ErrorCategory::not_convex, message); }

// The plane filter of the triple t, the coordinates of its vertices from
// coords(v): S(x) = orient3d(t[0], t[1], t[2], x) to within its bound.
template <class CoordsOf>
PlaneFilter triple_plane(const std::array<VertexId, 3>& t, const CoordsOf& coords,
                         const PlaneFilterScale& scale) {
  return PlaneFilter::of(coords(t[0]), coords(t[1]), coords(t[2]), scale);
}

// The input's vertices with their double approximations, made once, for
// the filtered predicates, and the extent of the semi-static plane filter
// over all of them (plane_filter.hpp), which decides most orientations of a
// mesh in general position in a few multiplications. Its decisions count as
// filtered ones, like those of the running-error filter.
class Points {
 public:
  explicit Points(const Mesh& mesh) : mesh_(mesh), counters_(predicate_counters()) {
    approx_.reserve(mesh.num_vertices());
    for (VertexId v : mesh.vertices()) extent_.add(approx_.emplace_back(ApproxVec3::of(mesh.position(v))));
    scale_ = extent_.scale();
  }
  Vec3Ref operator[](VertexId v) const { return {mesh_.position(v), approx_[v.index()]}; }
  [[nodiscard]] const ApproxVec3& approx(VertexId v) const { return approx_[v.index()]; }
  [[nodiscard]] const PlaneFilterExtent& extent() const { return extent_; }
  [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(approx_.size()); }

  // The side of x of the plane through the triple t when a filter proves it:
  // the semi-static one first, else the running-error one.
  [[nodiscard]] std::optional<Sign> side_if_certain(const std::array<VertexId, 3>& t, VertexId x) const {
    if (const std::optional<Sign> side = semi_static_side(t, x)) return side;
    return orient3d_if_certain((*this)[t[0]], (*this)[t[1]], (*this)[t[2]], (*this)[x]);
  }

  // True when the semi-static filter proves x off the plane of the triple t:
  // then t is not collinear (for three points on a line the determinant
  // vanishes at every x). False says nothing.
  [[nodiscard]] bool surely_spans_plane(const std::array<VertexId, 3>& t, VertexId x) const {
    return semi_static_side(t, x).has_value();
  }

 private:
  // The side of x of the plane through t when the semi-static filter
  // proves it (counted as a filtered decision).
  [[nodiscard]] std::optional<Sign> semi_static_side(const std::array<VertexId, 3>& t, VertexId x) const {
    const auto coords = [this](VertexId v) { return coords_of(approx_[v.index()]); };
    const PlaneFilter plane = triple_plane(t, coords, scale_);
    const std::optional<Sign> side = plane.sign_if_certain(plane.value(coords(x)));
    if (side) ++counters_.filtered;
    return side;
  }

  const Mesh& mesh_;
  PredicateCounters& counters_;
  std::vector<ApproxVec3> approx_;
  PlaneFilterExtent extent_;
  PlaneFilterScale scale_;
};

// The plane of a face: its primitive integer normal, oriented like the face
// (a positive multiple of its area vector), and the normal's approximation.
// Every use of a face normal in steps 2-6 is a sign that a positive factor
// does not change, so this is as good as the area vector, whose numbers grow
// with the face when its vertices have different denominators.
struct FacePlane {
  Vec3 normal;
  ApproxVec3 approx;
  [[nodiscard]] Vec3Ref ref() const { return {normal, approx}; }
};

// The plane through `point` with a primitive integer normal: the side of a
// point on it is one integer comparison after the filter (coplanar points,
// which no filter decides, are what faces of more than three vertices and
// flat meshes are made of). The offset lives in the caller's `storage`, which
// keeps its limbs from face to face.
struct IntegerPlane {
  Vec3Ref normal;
  const Rational& offset;
  Approx offset_approx;
  IntegerPlane(Vec3Ref n, const Vec3& point, Rational& storage) : normal(n), offset(storage) {
    thread_local detail::DotScratch scratch;
    detail::integer_dot(n.exact, point, scratch, storage);
    offset_approx = Approx::of(offset);
  }
  [[nodiscard]] Sign side(Vec3Ref p) const { return side_of_plane(p, normal, offset, offset_approx); }
};

FacePlane plane_of(Vec3 normal) {
  const ApproxVec3 approx = ApproxVec3::of(normal);
  return {std::move(normal), approx};
}

using detail::PolygonCheck;
using detail::PolygonFault;
using detail::check_convex_polygon;
using detail::describe_fault;

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

// A face's corners in vertex order, with their vertex indices (for messages).
struct FaceCorners {
  FaceId f;
  std::vector<Vec3Ref> pts;
  std::vector<std::uint32_t> ids;
  Rational plane_offset;  // storage for the face's IntegerPlane
};

// The primitive normals of the faces that need one, made at most once per
// face from its plane triple (FaceChecks): faces of more than three vertices
// (step 2's planarity and polygon checks), face 0 when the filter cannot
// place a vertex against it (step 3), the two faces of an edge that the
// filter cannot classify (step 4: coplanar or nearly) and the first face of a
// merged facet (step 5). A triangulated surface in general position needs
// none: the filtered orientations of its vertices decide it.
class FaceNormals {
 public:
  FaceNormals(const Mesh& mesh, const Points& points, const std::vector<std::array<VertexId, 3>>& triple)
      : points_(points), triple_(triple), slot_(mesh.num_faces(), no_index) {}
  const FacePlane& operator()(std::uint32_t f) {
    if (slot_[f] == no_index) {
      slot_[f] = static_cast<std::uint32_t>(planes_.size());
      FacePlane& plane = planes_.emplace_back();
      const std::array<VertexId, 3>& t = triple_[f];
      detail::primitive_normal(points_[t[0]], points_[t[1]], points_[t[2]], arena_, general_, plane.normal,
                               plane.approx);
    }
    return planes_[slot_[f]];
  }
  [[nodiscard]] bool has(std::uint32_t f) const { return slot_[f] != no_index; }

 private:
  const Points& points_;
  const std::vector<std::array<VertexId, 3>>& triple_;
  std::vector<std::uint32_t> slot_;
  detail::LimbArena arena_;       // before the normals that point into it, so that it outlives them
  std::deque<FacePlane> planes_;  // a deque: a normal never moves once made
  Vec3 general_;                  // keeps its limbs from face to face
};

// A vertex to show a face's corners not collinear (not_collinear): the
// mesh's first, or its last for a face through the first.
VertexId collinearity_witness(const FaceCorners& face, const Points& points) {
  const bool through_first = std::find(face.ids.begin(), face.ids.end(), 0u) != face.ids.end();
  return through_first ? VertexId(points.size() - 1) : VertexId(0);
}

// Corners 0, 1 and k of the face are not collinear. The witness off their
// plane proves it for most faces in a few floating-point operations; faces
// that hold their witness, or that the filter cannot place, take the exact
// test.
bool not_collinear(const FaceCorners& face, const Points& points, VertexId witness, std::size_t k) {
  const std::array<VertexId, 3> t{VertexId(face.ids[0]), VertexId(face.ids[1]), VertexId(face.ids[k])};
  if (points.surely_spans_plane(t, witness)) return true;
  return !collinear(face.pts[0], face.pts[1], face.pts[k]);
}

enum class FaceVerdict {
  passed,
  failed_in_plane,  // planar (the triple spans its plane), but not a convex polygon
  failed            // collinear or not planar
};

// Step 2 in O(m) predicates on small numbers, for a face that passes it: p0,
// p1 and the first pk off their line span the face's plane if it is planar,
// and if it is moreover a convex polygon, the triangle p0 p1 pk (three of its
// vertices in cyclic order, not collinear) turns like the polygon, so it
// orients the plane like the face: its normal is a positive multiple of the
// area vector and the polygon check against it decides as the check against
// the area vector would. Writes that triple into `triple` and, for a face that
// passes, the corner flags into `corner`.
FaceVerdict check_face(FaceCorners& face, const Points& points, FaceNormals& normals,
                       std::array<VertexId, 3>& triple, std::vector<char>& corner) {
  const std::vector<Vec3Ref>& pts = face.pts;
  const std::size_t m = pts.size();
  std::size_t k = 2;
  const VertexId witness = collinearity_witness(face, points);
  while (k < m && !not_collinear(face, points, witness, k)) ++k;
  if (k == m) return FaceVerdict::failed;
  triple = {VertexId(face.ids[0]), VertexId(face.ids[1]), VertexId(face.ids[k])};
  if (m == 3) {
    corner.assign(3, 1);  // a triangle of nonzero area turns left at each corner
    return FaceVerdict::passed;
  }
  const Vec3Ref normal = normals(face.f.index()).ref();
  const IntegerPlane plane(normal, pts[0].exact, face.plane_offset);
  for (std::size_t i = 2; i < m; ++i)
    if (i != k && plane.side(pts[i]) != Sign::zero) return FaceVerdict::failed;
  PolygonCheck c = check_convex_polygon(pts, normal);
  if (c.fault != PolygonFault::none) return FaceVerdict::failed_in_plane;
  corner = std::move(c.corner);
  return FaceVerdict::passed;
}

// Step 2 as stated, on the exact area vector N_f, for a face that
// check_face refused: throws its first fault. `normal` is the plane of
// the face when it is known to be planar (then N_f is a multiple of it, and
// a positive multiple stands in for N_f in the polygon check).
[[noreturn]] void report_face_fault(const FaceCorners& face, const FacePlane* normal) {
  const std::vector<Vec3Ref>& pts = face.pts;
  const std::string name = "face " + str(face.f.index());
  const Vec3 n = detail::area_vector(pts.size(), [&pts](std::size_t i) -> const Vec3& { return pts[i].exact; });
  if (is_zero(n)) {
    bool collinear_face = true;
    for (std::size_t i = 2; i < pts.size() && collinear_face; ++i)
      collinear_face = collinear(pts[0], pts[1], pts[i]);
    if (collinear_face) throw Error(ErrorCategory::degenerate, name + " has zero area (its vertices are collinear)");
    not_convex(name + " has zero signed area (it is not a convex polygon)");
  }
  if (pts.size() > 3) {
    FacePlane plane;
    if (normal != nullptr) {
      plane = *normal;
      if (sign_dot(n, normal->normal) == Sign::negative) plane = plane_of(-normal->normal);
    } else {
      plane = plane_of(n);
      for (std::size_t i = 1; i < pts.size(); ++i)
        if (compare_dot(pts[i], pts[0], plane.ref()) != Sign::zero)
          not_convex(name + " is not planar (vertex " + str(face.ids[i]) + " is off the plane of the others)");
    }
    PolygonCheck c = check_convex_polygon(pts, plane.ref());
    if (c.fault != PolygonFault::none)
      not_convex(name + " is not a convex polygon: it " + describe_fault(c, face.ids));
  }
  // Not reached: check_face refuses only faces that fail (see there).
  throw Error(ErrorCategory::not_convex, name + " could not be checked");
}

// What step 2 finds: per face three of its vertices, not collinear, that
// span its plane and turn like it (its plane triple: orient3d against them is
// the side of its plane, signed by its orientation), and per halfedge whether
// its origin is a corner of its face (a strict turn).
struct FaceChecks {
  explicit FaceChecks(const Mesh& mesh) : triple(mesh.num_faces()), corner(mesh.num_halfedges(), 0) {}
  std::vector<std::array<VertexId, 3>> triple;
  std::vector<char> corner;
};

// 2. Faces: zero area, planarity, convexity.
void check_faces(const Mesh& mesh, const Points& points, FaceNormals& normals, FaceChecks& out) {
  FaceCorners face{FaceId(0), {}, {}, {}};
  std::vector<char> corner;
  for (FaceId f : mesh.faces()) {
    face.f = f;
    face.pts.clear();
    face.ids.clear();
    for (HalfedgeId h : mesh.face_halfedges(f)) {
      face.pts.push_back(points[mesh.from(h)]);
      face.ids.push_back(mesh.from(h).index());
    }
    const FaceVerdict verdict = check_face(face, points, normals, out.triple[f.index()], corner);
    if (verdict == FaceVerdict::failed_in_plane) report_face_fault(face, &normals(f.index()));
    if (verdict == FaceVerdict::failed) report_face_fault(face, nullptr);
    std::size_t i = 0;
    for (HalfedgeId h : mesh.face_halfedges(f)) out.corner[h.index()] = corner[i++];
  }
}


// 3. Flat: every vertex on the plane of face 0. The filter places the first
// vertex off it at once in general position; the vertices it cannot place
// (those on the plane, all of them in a flat mesh) take the integer test.
void check_not_flat(const Mesh& mesh, const Points& points, const std::array<VertexId, 3>& t0,
                    FaceNormals& normals) {
  Rational offset;
  std::optional<IntegerPlane> plane0;
  for (VertexId v : mesh.vertices()) {
    if (points.side_if_certain(t0, v)) return;
    if (!plane0) plane0.emplace(normals(0).ref(), points[t0[0]].exact, offset);
    if (plane0->side(points[v]) != Sign::zero) return;
  }
  throw Error(ErrorCategory::degenerate, "flat polyhedron: all vertices are coplanar (zero volume)");
}

// What step 4 finds: the faces joined by coplanar edges, and whether the
// mesh is consistently inward (then flipped).
struct EdgeClasses {
  UnionFind coplanar;
  bool flip;
};

// 4. Edges. For the edge p -> q of face f and q -> p of face g, the
// classical test is the sign of det[N_f, N_g, q - p] (N the outward area
// normals): positive iff the edge is convex. Without the normals: the planes
// of f and g both contain the line pq, and g, a convex polygon (step 2) with
// the side q -> p, lies in its plane on one side of that line, so the
// vertices of g off the line lie strictly on one side of f's plane and the
// others on it. Writing x - p = a (q - p) + t (N_g x (q - p)) for such an x,
// g's counterclockwise turn from q -> p to x gives t < 0, and then
// dot(N_f, x - p) = t det[N_f, N_g, q - p]: the edge is convex iff x is below
// f's plane, reflex iff above. The filters (Points::side_if_certain) decide
// that for a vertex of g's plane triple other than p and q whenever it is off
// f's plane by more than their error bounds; otherwise (coplanar faces, a vertex of g on the line pq, or
// a nearly flat edge) the classical test decides, on the primitive normals,
// and so it does at once when both were made already (a mesh whose faces are
// coplanar in large groups, where the filter would fail edge after edge).
// Two primitive integer vectors are parallel exactly when they are equal (the
// same direction: a coplanar edge, merged) or opposite (a zero-angle fold).
// a == -b, without making -b (canonical rationals).
bool opposite(const Vec3& a, const Vec3& b) {
  for (int i = 0; i < 3; ++i)
    if (sgn(a[i]) != -sgn(b[i]) || mpz_cmpabs(a[i].get_num_mpz_t(), b[i].get_num_mpz_t()) != 0 ||
        mpz_cmp(a[i].get_den_mpz_t(), b[i].get_den_mpz_t()) != 0)
      return false;
  return true;
}

EdgeKind edge_kind(const Points& points, const FaceChecks& faces, FaceNormals& normals, VertexId p, VertexId q,
                   std::uint32_t f, std::uint32_t g) {
  if (!normals.has(f) || !normals.has(g)) {
    const std::array<VertexId, 3>& t = faces.triple[g];
    const VertexId x = t[0] != p && t[0] != q ? t[0] : (t[1] != p && t[1] != q ? t[1] : t[2]);
    if (const std::optional<Sign> side = points.side_if_certain(faces.triple[f], x))
      return *side == Sign::negative ? EdgeKind::convex : EdgeKind::reflex;
  }
  const FacePlane& n_f = normals(f);
  const FacePlane& n_g = normals(g);
  if (n_f.normal == n_g.normal) return EdgeKind::coplanar;
  if (opposite(n_f.normal, n_g.normal)) return EdgeKind::fold;
  return sign_triple_with_difference(n_f.ref(), n_g.ref(), points[p], points[q]) == Sign::positive
             ? EdgeKind::convex
             : EdgeKind::reflex;
}

EdgeClasses classify_edges(const Mesh& mesh, const Points& points, const FaceChecks& faces, FaceNormals& normals) {
  std::vector<EdgeKind> kind(mesh.num_edges());
  std::size_t num_convex = 0, num_reflex = 0;
  EdgeClasses out{UnionFind(mesh.num_faces()), false};
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = Mesh::halfedge(e);
    const std::uint32_t f = mesh.face(h).index(), g = mesh.face(Mesh::twin(h)).index();
    const EdgeKind k = edge_kind(points, faces, normals, mesh.from(h), mesh.to(h), f, g);
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
  std::vector<std::uint32_t> num_faces;   // the number of faces of each region

  Regions(const Mesh& m, UnionFind& coplanar) : mesh(m), of_face(m.num_faces()) {
    std::vector<std::uint32_t> id_of_root(m.num_faces(), no_index);
    for (std::uint32_t f = 0; f < m.num_faces(); ++f) {
      const std::uint32_t r = coplanar.find(f);
      if (id_of_root[r] == no_index) {
        id_of_root[r] = static_cast<std::uint32_t>(first_face.size());
        first_face.push_back(f);
        num_faces.push_back(0);
      }
      of_face[f] = id_of_root[r];
      ++num_faces[of_face[f]];
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
// The cycles are stored one after the other in the order found (one array,
// not a vector per region: a load makes one region per face).
struct BoundaryCycles {
  std::vector<HalfedgeId> halfedges;
  std::vector<std::uint32_t> begin, size;  // per region; size 0: none found
  [[nodiscard]] std::span<const HalfedgeId> operator[](std::uint32_t r) const {
    return {halfedges.data() + begin[r], size[r]};
  }
};

BoundaryCycles boundary_cycles(const Regions& regions) {
  const Mesh& mesh = regions.mesh;
  const std::uint32_t nh = mesh.num_halfedges();
  BoundaryCycles cycle{{}, std::vector<std::uint32_t>(regions.size(), 0), std::vector<std::uint32_t>(regions.size(), 0)};
  std::vector<char> visited(nh, 0);
  for (HalfedgeId start : mesh.halfedges()) {
    if (visited[start.index()] || !regions.is_border(start)) continue;
    const std::uint32_t r = regions.of(start);
    if (cycle.size[r] != 0)
      not_convex(regions.facet_name(r) +
                 " (coplanar faces merged) has more than one boundary cycle (a hole)");
    cycle.begin[r] = static_cast<std::uint32_t>(cycle.halfedges.size());
    HalfedgeId h = start;
    std::uint32_t steps = 0;
    do {
      visited[h.index()] = 1;
      cycle.halfedges.push_back(h);
      HalfedgeId n = mesh.next(h);
      while (!regions.is_border(n) && ++steps <= nh) n = mesh.next(Mesh::twin(n));
      h = n;
    } while (h != start && ++steps <= 2 * nh);
    if (h != start) throw Error(ErrorCategory::topology, "corrupt mesh: a facet boundary does not close");
    cycle.size[r] = static_cast<std::uint32_t>(cycle.halfedges.size()) - cycle.begin[r];
  }
  for (std::uint32_t r = 0; r < regions.size(); ++r)
    if (cycle.size[r] < 3) not_convex(regions.facet_name(r) + " has no proper boundary");
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

// The corner flags of a facet's boundary cycle: those of its face when the
// facet is one face (the cycle is that face's, perhaps from another start:
// the check of step 2 against the same plane decided them, and a strictly
// convex polygon stays one from any start), else from the polygon check.
// Written into c, whose storage the caller reuses from facet to facet.
void cycle_corners(const Regions& regions, std::span<const HalfedgeId> cycle, const Points& points,
                   const FaceChecks& faces, FaceNormals& normals, std::uint32_t r, PolygonCheck& c) {
  const Mesh& mesh = regions.mesh;
  if (regions.num_faces[r] == 1) {
    c.fault = PolygonFault::none;
    c.corner.clear();
    for (HalfedgeId h : cycle) c.corner.push_back(faces.corner[h.index()]);
    return;
  }
  std::vector<Vec3Ref> pts;
  pts.reserve(cycle.size());
  for (HalfedgeId h : cycle) pts.push_back(points[mesh.from(h)]);
  c = check_convex_polygon(pts, normals(regions.first_face[r]).ref());
}

// Facet polygons, and corners agree with extremality. The corners of facet
// r, as input vertex indices, are face r of the returned soup (which has no
// points).
PolygonSoup facet_corners(const Regions& regions, const BoundaryCycles& cycle, const Points& points,
                          const FaceChecks& faces, FaceNormals& normals, const FacetsAtVertices& facets_at) {
  const Mesh& mesh = regions.mesh;
  PolygonSoup corners;
  corners.face_offsets.reserve(regions.size() + 1);
  std::vector<std::uint32_t> ids;
  PolygonCheck c;
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    ids.clear();
    for (HalfedgeId h : cycle[r]) ids.push_back(mesh.from(h).index());
    cycle_corners(regions, cycle[r], points, faces, normals, r, c);
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
      if (c.corner[i] != 0) corners.face_indices.push_back(ids[i]);
    }
    corners.face_offsets.push_back(static_cast<std::uint32_t>(corners.face_indices.size()));
  }
  return corners;
}

// 7. The result's facets: extreme vertices renumbered in input order, facets
// ordered by their smallest input face, each starting at its smallest vertex
// index, as index lists (the soup has no points yet).
PolygonSoup merged_faces(const Mesh& mesh, const PolygonSoup& facet_corners, const FacetsAtVertices& facets_at,
                         bool flip) {
  std::vector<std::uint32_t> new_index(mesh.num_vertices(), no_index);
  std::uint32_t kept = 0;
  for (std::uint32_t v = 0; v < mesh.num_vertices(); ++v)
    if (facets_at.extreme(v)) new_index[v] = kept++;
  PolygonSoup out;
  out.face_offsets.reserve(facet_corners.face_offsets.size());
  out.face_indices.reserve(facet_corners.face_indices.size());
  std::vector<std::uint32_t> facet;
  for (std::size_t r = 0; r < facet_corners.num_faces(); ++r) {
    facet.clear();
    for (std::uint32_t v : facet_corners.face(r)) facet.push_back(new_index[v]);
    if (flip) std::reverse(facet.begin(), facet.end());
    std::rotate(facet.begin(), std::min_element(facet.begin(), facet.end()), facet.end());
    out.add_face(facet);
  }
  return out;
}

// The result's points: the extreme vertices in input order. Copied, or,
// when every vertex is extreme and the caller hands the input over
// (`owned`: from_soup's own mesh, which is not const, so writing through the
// const accessor is defined), moved as one vector: the input mesh has no
// positions afterwards.
std::vector<Vec3> kept_points(const Mesh& mesh, const FacetsAtVertices& facets_at, Mesh* owned) {
  const auto kept = static_cast<std::size_t>(
      std::count_if(facets_at.count.begin(), facets_at.count.end(), [](std::uint32_t c) { return c >= 3; }));
  if (owned != nullptr && kept == mesh.num_vertices())
    return std::move(const_cast<std::vector<Vec3>&>(owned->positions()));
  std::vector<Vec3> points;
  points.reserve(kept);  // growing would copy every Rational (their moves are not noexcept)
  for (std::uint32_t v = 0; v < mesh.num_vertices(); ++v)
    if (facets_at.extreme(v)) points.push_back(mesh.position(VertexId(v)));
  return points;
}

bool keeps_every_vertex(const Mesh& mesh, const FacetsAtVertices& facets_at) {
  for (std::uint32_t v = 0; v < mesh.num_vertices(); ++v)
    if (!facets_at.extreme(v)) return false;
  return true;
}

// The result's mesh. The points of from_soup's own mesh were checked when it
// was built (canonical and distinct), so then only the topology is; a
// caller's mesh may come from Mesh::with_positions, which checks nothing.
Mesh merged_mesh(const Mesh& mesh, const PolygonSoup& facet_corners, const FacetsAtVertices& facets_at, bool flip,
                 Mesh* owned) {
  // from_soup's own mesh (points checked) with nothing merged, dropped or
  // turned (every facet is its face with all its vertices, every vertex
  // extreme, the orientation kept): the merged soup is the input's with each
  // cycle rotated to its smallest vertex, whose mesh is the input's
  // connectivity with the faces' stored halfedges moved there (the numbering
  // of Mesh::from_soup), without a second build.
  if (owned != nullptr && !flip && facet_corners.num_faces() == mesh.num_faces() &&
      facet_corners.face_indices.size() == mesh.num_halfedges() && keeps_every_vertex(mesh, facets_at))
    return MeshAccess::with_faces_from_smallest_vertex(mesh, kept_points(mesh, facets_at, owned));
  PolygonSoup out = merged_faces(mesh, facet_corners, facets_at, flip);
  out.points = kept_points(mesh, facets_at, owned);
  Mesh merged;
  try {
    merged = owned != nullptr ? MeshAccess::from_distinct_points(std::move(out)) : Mesh::from_soup(std::move(out));
  } catch (const Error& e) {
    not_convex(std::string("the merged facets do not form a closed surface: ") + e.what());
  }
  return merged;
}

// The result: its planes are made when first asked for, from each facet's
// first three corners (facet_planes.hpp), which are not collinear because
// step 5 checked every facet to be a strictly convex polygon of its corners
// and the facets turn like their faces, flipped with the mesh. The input's
// positions may have moved into `merged`: its vertices are counted by
// facets_at.
ConvexPolyhedron merged_polyhedron(Mesh merged, const Points& points, const FacetsAtVertices& facets_at) {
  detail::PolyhedronParts parts;
  parts.vertex_approx.reserve(merged.num_vertices());
  for (std::uint32_t v = 0; v < facets_at.count.size(); ++v)
    if (facets_at.extreme(v)) parts.vertex_approx.push_back(points.approx(VertexId(v)));
  parts.mesh = std::move(merged);
  return PolyhedronAccess::make(std::move(parts));
}

// 8. Global: an interior point o below every facet, and a ray from o that
// crosses facet 0 only. The facets of p are the regions, in order.
// The facets' planes are signed by their first three corners (first_corners),
// in orientations of the result's vertices, so that the check does not make
// the planes: S_f(x) = orient3d(a, b, c, x) is the side of x, a positive
// multiple of dot(N, x - a) for the outward normal N. With w a vertex below
// facet 0, o = (a + b + c + w) / 4 and the ray runs from o through g = (a + b
// + c) / 3, inside facet 0, in the direction dir = 12 (g - o); it leaves
// through f's plane iff dot(N, dir) > 0, that is S_f(g) > S_f(o), and meets
// the closed facet iff det[from - o, to - o, dir] >= 0 along each of its
// edges, that is orient3d(o, from, to, g) >= 0. Written so, every sign is an
// orientation of points, and the semi-static plane filter decides most of
// them in a few multiplications, its scale taken over the input's vertices
// (the result's are among them, with the same approximations) and the
// approximations of o and g; a difference S_f(g) - S_f(o) is proved by
// difference_sign_if_certain. Exact predicates on dir decide the rest.
class GlobalCheck {
 public:
  GlobalCheck(const ConvexPolyhedron& p, const Regions& regions, PlaneFilterExtent extent)
      : p_(p), m_(p.mesh()), regions_(regions), counters_(predicate_counters()) {
    const std::array<VertexId, 3> t0 = first_corners(m_, FaceId(0));
    const Vec3* w = nullptr;
    for (VertexId v : m_.vertices())
      if (orient3d(ref(t0[0]), ref(t0[1]), ref(t0[2]), ref(v)) == Sign::negative) {
        w = &m_.position(v);
        break;
      }
    if (w == nullptr) not_convex(regions_.facet_name(0) + " has every vertex on its plane");
    const Vec3 abc = m_.position(t0[0]) + m_.position(t0[1]) + m_.position(t0[2]);
    o_ = Rational(1, 4) * (abc + *w);
    dir_ = abc - Rational(3) * *w;
    o_approx_ = ApproxVec3::of(o_);
    dir_approx_ = ApproxVec3::of(dir_);
    const ApproxVec3 g_approx = ApproxVec3::of(Rational(1, 3) * abc);
    extent.add(o_approx_);
    extent.add(g_approx);
    scale_ = extent.scale();
    o_coords_ = coords_of(o_approx_);
    g_coords_ = coords_of(g_approx);
  }

  void run() {
    leaving_.assign(m_.num_faces(), std::nullopt);
    for (FaceId f : m_.faces())
      if (!below(f))
        not_convex("the surface is locally convex but not convex: an interior point lies above " +
                   regions_.facet_name(f.index()));
    for (FaceId f : m_.faces())
      if (f.index() != 0 && ray_leaves_through(f) && ray_meets(f))
        not_convex("the surface is locally convex but winds around its interior more than once (" +
                   regions_.facet_name(0) + " and " + regions_.facet_name(f.index()) +
                   " overlap as seen from inside)");
  }

 private:
  [[nodiscard]] Vec3Ref ref(VertexId v) const { return detail::vertex_ref(p_, v); }
  [[nodiscard]] Coords coords(VertexId v) const { return coords_of(detail::vertex_approx(p_, v)); }
  [[nodiscard]] Vec3Ref o_ref() const { return {o_, o_approx_}; }
  [[nodiscard]] Vec3Ref dir_ref() const { return {dir_, dir_approx_}; }
  [[nodiscard]] PlaneFilter plane(const std::array<VertexId, 3>& t) const {
    const auto vertex_coords = [this](VertexId v) { return coords(v); };
    return triple_plane(t, vertex_coords, scale_);
  }
  // A sign the filter proved, counted.
  [[nodiscard]] std::optional<Sign> counted(std::optional<Sign> sign) const {
    if (sign) ++counters_.filtered;
    return sign;
  }

  // S_f(o) < 0. The facet's plane also answers, when the filter can, the
  // question ray_leaves_through asks later: its sign is kept in leaving_, so
  // that each plane is made once.
  [[nodiscard]] bool below(FaceId f) {
    const std::array<VertexId, 3> t = first_corners(m_, f);
    const PlaneFilter filter = plane(t);
    const double s_o = filter.value(o_coords_);
    leaving_[f.index()] = difference_sign_if_certain(filter.value(g_coords_), s_o, filter.bound);
    if (const std::optional<Sign> side = counted(filter.sign_if_certain(s_o))) return *side == Sign::negative;
    return orient3d(ref(t[0]), ref(t[1]), ref(t[2]), o_ref()) == Sign::negative;
  }

  // dot(N_f, dir) > 0, i.e. S_f(g) > S_f(o).
  [[nodiscard]] bool ray_leaves_through(FaceId f) const {
    if (const std::optional<Sign> s = counted(leaving_[f.index()])) return *s == Sign::positive;
    const std::array<VertexId, 3> t = first_corners(m_, f);
    return sign_triple_of_differences(dir_ref(), ref(t[0]), ref(t[1]), ref(t[0]), ref(t[2])) ==
           Sign::positive;
  }

  // det[from - o, to - o, dir] >= 0 along every edge of f.
  [[nodiscard]] bool ray_meets(FaceId f) const {
    for (HalfedgeId h : m_.face_halfedges(f)) {
      const PlaneFilter filter = PlaneFilter::of(o_coords_, coords(m_.from(h)), coords(m_.to(h)), scale_);
      const std::optional<Sign> side = counted(filter.sign_if_certain(filter.value(g_coords_)));
      // det[from - o, to - o, dir] = det[dir, from - o, to - o]
      const Sign s =
          side ? *side
               : sign_triple_of_differences(dir_ref(), o_ref(), ref(m_.from(h)), o_ref(), ref(m_.to(h)));
      if (s == Sign::negative) return false;
    }
    return true;
  }

  const ConvexPolyhedron& p_;
  const Mesh& m_;
  const Regions& regions_;
  PredicateCounters& counters_;
  Vec3 o_, dir_;
  ApproxVec3 o_approx_{}, dir_approx_{};
  PlaneFilterScale scale_;
  Coords o_coords_{}, g_coords_{};
  std::vector<std::optional<Sign>> leaving_;  // by facet: the filter's sign of S_f(g) - S_f(o), if proved
};

// from_mesh; `owned` is the mesh itself when the caller hands it over
// (from_soup), whose points may then move into the result (kept_points).
ConvexPolyhedron checked_polyhedron(const Mesh& mesh, Mesh* owned) {
  if (mesh.num_faces() == 0 || mesh.num_vertices() == 0) throw Error(ErrorCategory::topology, "empty mesh");
  // Steps 1-6 check the input, step 7 builds the result and step 8 checks it
  // globally (the file comment says why that suffices).
  check_sphere(mesh);
  const Points points(mesh);
  FaceChecks faces(mesh);
  FaceNormals normals(mesh, points, faces.triple);
  check_faces(mesh, points, normals, faces);
  check_not_flat(mesh, points, faces.triple[0], normals);
  EdgeClasses edges = classify_edges(mesh, points, faces, normals);
  const Regions regions(mesh, edges.coplanar);
  const BoundaryCycles cycles = boundary_cycles(regions);
  const FacetsAtVertices facets_at = facets_at_vertices(regions);
  const PolygonSoup corners = facet_corners(regions, cycles, points, faces, normals, facets_at);
  // From here on `mesh` may have no positions (kept_points): only counts and
  // approximations of the input are read.
  Mesh merged = merged_mesh(mesh, corners, facets_at, edges.flip, owned);
  ConvexPolyhedron p = merged_polyhedron(std::move(merged), points, facets_at);
  GlobalCheck(p, regions, points.extent()).run();
  return p;
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

ConvexPolyhedron ConvexPolyhedron::from_soup(PolygonSoup soup) {
  Mesh mesh = Mesh::from_soup(std::move(soup));
  return checked_polyhedron(mesh, &mesh);
}

ConvexPolyhedron::ConvexPolyhedron() = default;
ConvexPolyhedron::~ConvexPolyhedron() = default;

namespace {

// The mesh of a copy. A copy's Vec3 values own their limbs (copying a
// rational allocates them), so it does not keep the original's arena alive:
// positions in an arena are copied. Other meshes are shared (immutable),
// a sum's packed vertices (packed_vectors.hpp) with the limbs they keep.
Mesh mesh_of_copy(const Mesh& mesh, const std::shared_ptr<const detail::LimbArena>& limbs) {
  if (limbs == nullptr || MeshAccess::packed_positions(mesh) != nullptr) return mesh;
  return mesh.with_positions(mesh.positions());
}

}  // namespace

// Planes and offsets made already are copied, those not yet made are made
// by the copy when it needs them (into an arena of its own).
ConvexPolyhedron::ConvexPolyhedron(const ConvexPolyhedron& other)
    : mesh_(mesh_of_copy(other.mesh_, other.impl_ != nullptr ? other.impl_->exact_limbs : nullptr)) {
  if (other.impl_ == nullptr) return;
  impl_ = std::make_unique<Impl>();
  impl_->approx = other.impl_->approx;
  impl_->vertex_approx = other.impl_->vertex_approx;
  if (!other.impl_->planes) return;
  const detail::FacetPlanes* made = other.impl_->planes_made.load(std::memory_order_acquire);
  if (made == nullptr) {
    impl_->planes = std::make_shared<detail::PlaneStore>();
    return;
  }
  detail::FacetPlanes copied = *made;
  if (const auto* offsets = other.impl_->planes->offsets_if_made(); offsets != nullptr && copied.offsets.empty())
    copied.offsets = *offsets;
  impl_->planes = std::make_shared<detail::PlaneStore>(std::move(copied), nullptr);
  impl_->planes_made.store(&impl_->planes->get(mesh_, impl_->approx->vertices), std::memory_order_release);
}
ConvexPolyhedron::ConvexPolyhedron(ConvexPolyhedron&& other) noexcept = default;
ConvexPolyhedron& ConvexPolyhedron::operator=(const ConvexPolyhedron& other) {
  ConvexPolyhedron copy(other);
  return *this = std::move(copy);
}
// By hand, so that the old arena goes only after the old values that point
// into it (destroying a view reads no limb, but the order keeps the rule simple).
ConvexPolyhedron& ConvexPolyhedron::operator=(ConvexPolyhedron&& other) noexcept {
  mesh_ = std::move(other.mesh_);
  impl_ = std::move(other.impl_);
  return *this;
}

ConvexPolyhedron PolyhedronAccess::make(detail::PolyhedronParts&& parts) {
  ConvexPolyhedron p;
  auto impl = std::make_unique<ConvexPolyhedron::Impl>();
  if (parts.limbs.capacity_bytes() > 0) {
    impl->exact_limbs = std::make_shared<const detail::LimbArena>(std::move(parts.limbs));
    MeshAccess::keep_limbs(parts.mesh, impl->exact_limbs);
  }
  impl->approx = std::make_shared<const detail::PolyhedronApproximations>(
      detail::PolyhedronApproximations{std::move(parts.vertex_approx)});
  impl->vertex_approx = impl->approx->vertices.data();
  impl->planes = parts.planes ? std::make_shared<detail::PlaneStore>(std::move(*parts.planes), impl->exact_limbs)
                              : std::make_shared<detail::PlaneStore>();
  p.mesh_ = std::move(parts.mesh);
  if (parts.planes)
    impl->planes_made.store(&impl->planes->get(p.mesh_, impl->approx->vertices), std::memory_order_release);
  p.impl_ = std::move(impl);
  return p;
}

const detail::FacetPlanes& PolyhedronAccess::make_planes(const ConvexPolyhedron& p) {
  static const detail::FacetPlanes none;  // a default-constructed instance has no facets
  ConvexPolyhedron::Impl* impl = p.impl_.get();
  if (impl == nullptr || !impl->planes) return none;
  const detail::FacetPlanes& made = impl->planes->get(p.mesh_, impl->approx->vertices);
  impl->planes_made.store(&made, std::memory_order_release);
  return made;
}

const Vec3& ConvexPolyhedron::normal(FaceId f) const { return PolyhedronAccess::planes(*this).exact_normals()[f.index()]; }
const Rational& ConvexPolyhedron::plane_offset(FaceId f) const {
  if (const Rational* made = PolyhedronAccess::made_offsets(*this)) return made[f.index()];
  (void)PolyhedronAccess::planes(*this);  // published, so that a copy takes them rather than making its own
  return impl_->planes->offsets(mesh_, impl_->approx->vertices)[f.index()];
}

const Rational* PolyhedronAccess::made_offsets(const ConvexPolyhedron& p) noexcept {
  const auto* offsets = p.impl_ != nullptr && p.impl_->planes ? p.impl_->planes->offsets_if_made() : nullptr;
  return offsets != nullptr && !offsets->empty() ? offsets->data() : nullptr;
}

ConvexPolyhedron ConvexPolyhedron::from_mesh(const Mesh& mesh) { return checked_polyhedron(mesh, nullptr); }


bool ConvexPolyhedron::is_convex() const {
  const Mesh& m = mesh_;
  try {
    m.validate();
  } catch (const Error&) {
    return false;
  }
  if (euler_characteristic() != 2) return false;
  if (!impl_ || !impl_->approx || !impl_->planes || impl_->approx->vertices.size() != m.num_vertices())
    return false;
  const detail::FacetPlanes& made = PolyhedronAccess::planes(*this);
  const std::span<const Vec3> normals = made.exact_normals();
  const auto& offsets = impl_->planes->offsets(m, impl_->approx->vertices);
  if (normals.size() != m.num_faces() || made.normal_approx.size() != m.num_faces() ||
      offsets.size() != m.num_faces())
    return false;
  std::vector<const Vec3*> pts;
  for (FaceId f : m.faces()) {
    pts.clear();
    for (HalfedgeId h : m.face_halfedges(f)) pts.push_back(&m.position(m.from(h)));
    const Vec3 n = cross(*pts[1] - *pts[0], *pts[2] - *pts[1]);
    if (is_zero(n) || primitive_direction(n) != normals[f.index()]) return false;
    if (dot(normals[f.index()], *pts[0]) != offsets[f.index()]) return false;
    for (const Vec3* q : pts)
      if (side_of_plane(*q, normals[f.index()], offsets[f.index()]) != Sign::zero) return false;
    std::vector<ApproxVec3> approx;
    for (const Vec3* q : pts) approx.push_back(ApproxVec3::of(*q));
    std::vector<Vec3Ref> refs;
    for (std::size_t i = 0; i < pts.size(); ++i) refs.push_back({*pts[i], approx[i]});
    const ApproxVec3 n_approx = ApproxVec3::of(n);
    PolygonCheck c = check_convex_polygon(refs, {n, n_approx});
    if (c.fault != PolygonFault::none) return false;
    if (std::count(c.corner.begin(), c.corner.end(), 1) != static_cast<std::ptrdiff_t>(pts.size())) return false;
  }
  for (VertexId v : m.vertices()) {
    std::uint32_t on = 0;
    for (FaceId f : m.faces()) {
      const Sign s = side_of_plane(m.position(v), normals[f.index()], offsets[f.index()]);
      if (s == Sign::positive) return false;
      on += s == Sign::zero;
    }
    if (on < 3) return false;
  }
  // Distinct planes: with every vertex on or below every plane, two facets
  // with equal normals would lie in one plane (covering it twice).
  std::set<Vec3> distinct(normals.begin(), normals.end());
  if (distinct.size() != normals.size()) return false;
  for (VertexId v : m.vertices()) {
    const ApproxVec3 a = ApproxVec3::of(m.position(v));
    const ApproxVec3& b = impl_->approx->vertices[v.index()];
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
  if (det == Sign::positive) return PolyhedronAccess::make(detail::trusted_parts(mesh_.with_positions(std::move(pts))));
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
  if (!impl_) return {};
  detail::PolyhedronParts p;
  p.mesh = mesh_.with_positions(std::move(pts));
  p.vertex_approx.reserve(num_vertices());
  for (VertexId v : p.mesh.vertices()) p.vertex_approx.push_back(ApproxVec3::of(p.mesh.position(v)));
  const detail::FacetPlanes& old = PolyhedronAccess::planes(*this);
  detail::FacetPlanes moved{old.normals, old.packed_normals, old.normal_approx, {}};
  // Offsets not made here are not made for the image either: it makes its
  // own when asked, equal to these shifted.
  if (const Rational* offsets = PolyhedronAccess::made_offsets(*this)) {
    moved.offsets.reserve(num_facets());
    for (FaceId f : mesh_.faces()) {
      moved.offsets.push_back(offsets[f.index()] + dot(old.exact_normals()[f.index()], offset));
      moved.offsets.back().canonicalize();
    }
  }
  p.planes = std::move(moved);
  return PolyhedronAccess::make(std::move(p));
}

ConvexPolyhedron ConvexPolyhedron::reflected() const {
  Mat3 minus;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) minus.m[i][j] = (i == j) ? -1 : 0;
  return transformed(minus, Vec3{0, 0, 0});
}

}  // namespace cvms
