// SPDX-License-Identifier: MIT
// Half-edge mesh construction from a polygon soup with full topology checks,
// the reference validator, and conversion back to a soup.
#include "cvms/mesh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "cvms/error.hpp"
#include "element_names.hpp"
#include "face_lists.hpp"
#include "huge_page_blocks.hpp"
#include "mesh_access.hpp"
#include "packed_vectors.hpp"
#include "no_index.hpp"
#include "representation_order.hpp"

namespace cvms {
namespace {

using detail::edge_name;
using detail::no_index;
using detail::str;

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCategory::topology, message); }

// The soup's index structure: offsets well formed, something to build, and
// counts that fit the 32-bit handles.
void check_soup_shape(const PolygonSoup& soup, std::size_t num_points) {
  const auto& offsets = soup.face_offsets;
  const auto& indices = soup.face_indices;
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != indices.size())
    throw Error(ErrorCategory::invalid_argument,
                "malformed polygon soup: face_offsets must start at 0 and end at face_indices.size()");
  const std::size_t num_faces = offsets.size() - 1;
  for (std::size_t f = 0; f < num_faces; ++f)
    if (offsets[f + 1] < offsets[f])
      throw Error(ErrorCategory::invalid_argument,
                  "malformed polygon soup: face_offsets decrease at face " + std::to_string(f));
  if (num_points == 0 || num_faces == 0)
    fail("empty mesh: " + std::to_string(num_points) + " points and " + std::to_string(num_faces) +
         " faces");
  // Halfedge ids go up to the number of corners; keep every id below the
  // invalid marker, and edge ids (h >> 1) well defined.
  if (num_points >= no_index || indices.size() >= (std::size_t{1} << 31) || num_faces >= no_index)
    throw Error(ErrorCategory::limit,
                "mesh too large for 32-bit handles: " + std::to_string(num_points) + " points, " +
                    std::to_string(indices.size()) + " face corners");
}

// Faces: size, range, repeated vertices. stamp[v] is the last face using v.
void check_faces(const PolygonSoup& soup, std::uint32_t n) {
  const auto& offsets = soup.face_offsets;
  const auto& indices = soup.face_indices;
  const auto num_faces = static_cast<std::uint32_t>(offsets.size() - 1);
  std::vector<std::uint32_t> stamp(n, no_index);
  for (std::uint32_t f = 0; f < num_faces; ++f) {
    const std::uint32_t deg = offsets[f + 1] - offsets[f];
    if (deg < 3) fail("face " + str(f) + " has " + str(deg) + " vertices (at least 3 are needed)");
    for (std::uint32_t c = offsets[f]; c < offsets[f + 1]; ++c) {
      const std::uint32_t v = indices[c];
      if (v >= n)
        fail("face " + str(f) + ": vertex index " + str(v) + " out of range (" + str(n) + " points)");
      if (stamp[v] == f) fail("face " + str(f) + " uses vertex " + str(v) + " more than once");
      stamp[v] = f;
    }
  }
  for (std::uint32_t v = 0; v < n; ++v)
    if (stamp[v] == no_index) fail("vertex " + str(v) + " is not used by any face (unreferenced vertex)");
}

// Whether q is canonical without a gcd: a denominator 1; or a one-limb
// denominator 2^a 5^b over a nonzero numerator that 2 does not divide when
// a > 0 and 5 does not divide when b > 0 (the only primes they could share).
// Every double and every decimal of up to 27 places the readers make is of
// this kind: a remainder or two here instead of a gcd per coordinate (the
// gcds were a tenth of loading Sphere6 from its shortest decimals).
bool surely_canonical(const Rational& q) noexcept {
  mpz_srcptr den = q.get_den_mpz_t();
  if (den->_mp_size != 1) return false;
  const mp_limb_t d = den->_mp_d[0];
  if (d == 1) return true;
  mpz_srcptr num = q.get_num_mpz_t();
  if (num->_mp_size == 0) return false;  // 0 over d != 1
  const int twos = std::countr_zero(d);
  const mp_limb_t fives = d >> twos;
  // The divisors of 5^27 (the largest power of 5 in a limb) are exactly the
  // powers of 5 up to it.
  constexpr mp_limb_t five_27 = 7450580596923828125u;
  if (five_27 % fives != 0) return false;
  if (twos > 0 && (num->_mp_d[0] & 1) == 0) return false;
  return fives == 1 || mpz_divisible_ui_p(num, 5) == 0;
}

// GMP's comparisons, hashing and arithmetic assume canonical fractions; a
// caller that built 0/3 by hand would otherwise get wrong answers.
void canonicalize_points(std::vector<Vec3>& points) {
  for (Vec3& p : points)
    for (int i = 0; i < 3; ++i)
      if (!surely_canonical(p[i])) p[i].canonicalize();
}

// A point's sort key for the duplicate check: a mix of the signed sizes and
// the lowest limbs of its coordinates' numerators and denominators, a
// function of the canonical representation, so that equal points get equal
// keys; distinct points may too, and are then told apart exactly. A few
// multiplications per point and no division (the double of a decimal
// coordinate takes one).
std::uint64_t mixed(std::uint64_t h, std::uint64_t word) noexcept {
  h = (h ^ word) * 0x9e3779b97f4a7c15u;
  return h ^ (h >> 29);
}

std::uint64_t point_key(const Vec3& p) noexcept {
  std::uint64_t h = 0;
  for (int i = 0; i < 3; ++i) {
    mpz_srcptr num = p[i].get_num_mpz_t();
    mpz_srcptr den = p[i].get_den_mpz_t();
    h = mixed(h, mpz_getlimbn(num, 0) + static_cast<std::uint64_t>(static_cast<std::int64_t>(num->_mp_size)));
    h = mixed(h, mpz_getlimbn(den, 0) + static_cast<std::uint64_t>(den->_mp_size));
  }
  return h;
}

struct KeyedPoint {
  std::uint64_t key;
  std::uint32_t index;
};

// Duplicate points: indices sorted lexicographically by (key, the exact
// position in the representation order, the index). The keys decide almost
// every comparison without reading a limb beyond the first; the exact order
// only splits points with equal keys. The tuple order is a strict weak order
// whose first two parts are equal exactly for equal points, so equal points
// form one run, in index order, and the cost is O(n log n) whatever the
// values: an input that makes every key equal (the keys are easy to collide)
// only turns the comparisons into exact ones (a hash set goes quadratic on
// points that share one hash). Reports the same pair a scan in index order
// would find first: the earliest second occurrence of any position, with the
// first occurrence of that position.
// \pre the coordinates are canonical.
void check_distinct_points(const std::vector<Vec3>& pts) {
  const auto n = static_cast<std::uint32_t>(pts.size());
  std::vector<KeyedPoint> order(n);
  for (std::uint32_t v = 0; v < n; ++v) order[v] = {point_key(pts[v]), v};
  const detail::RepresentationLess less;
  std::sort(order.begin(), order.end(), [&](const KeyedPoint& a, const KeyedPoint& b) {
    if (a.key != b.key) return a.key < b.key;
    if (less(pts[a.index], pts[b.index])) return true;
    return !less(pts[b.index], pts[a.index]) && a.index < b.index;
  });
  // Equal points have equal keys: comparing the keys first skips the exact
  // test for nearly every neighbour.
  const auto same = [&](const KeyedPoint& a, const KeyedPoint& b) {
    return a.key == b.key && pts[a.index] == pts[b.index];
  };
  std::uint32_t first = no_index, second = no_index;
  for (std::uint32_t k = 0; k + 1 < n; ++k) {
    const std::uint32_t a = order[k].index, b = order[k + 1].index;
    // Within a run of equal points, a is the first occurrence exactly when
    // the run starts at k; b, its successor, is the run's second occurrence.
    if (b < second && same(order[k], order[k + 1]) && (k == 0 || !same(order[k - 1], order[k]))) {
      first = a;
      second = b;
    }
  }
  if (second != no_index)
    fail("vertices " + str(first) + " and " + str(second) + " are at the same point (duplicate point)");
}

// Corners: corner c of face f (offsets[f] <= c < offsets[f + 1]) is the
// directed edge from indices[c] to indices of the next corner of f. Read off
// the offsets face by face rather than stored: three arrays of a corner each
// would be a large share (about a fifth) of building a sum's output mesh.
struct Corner {
  std::uint32_t at;        ///< c
  std::uint32_t next;      ///< the corner after c in its face
  std::uint32_t previous;  ///< the corner before c in its face
  std::uint32_t face;
};

// Calls visit(corner) for every corner, face by face.
template <class Visit>
void for_each_corner(const std::vector<std::uint32_t>& offsets, Visit&& visit) {
  const auto num_faces = static_cast<std::uint32_t>(offsets.size() - 1);
  for (std::uint32_t f = 0; f < num_faces; ++f) {
    const std::uint32_t b = offsets[f], e = offsets[f + 1];
    for (std::uint32_t c = b; c < e; ++c) visit(Corner{c, c + 1 == e ? b : c + 1, c == b ? e - 1 : c - 1, f});
  }
}

// The face of corner c, for messages. \pre every face has a corner
// (check_faces), so the offsets increase strictly.
std::uint32_t face_of_corner(const std::vector<std::uint32_t>& offsets, std::uint32_t c) {
  return static_cast<std::uint32_t>(std::upper_bound(offsets.begin(), offsets.end(), c) - offsets.begin() -
                                    1);
}

// Each corner keyed by the undirected vertex pair (smaller << 32 | larger)
// of its directed edge.
using KeyedCorners = detail::ScratchVector<std::pair<std::uint64_t, std::uint32_t>>;

// Group the directed edges by their undirected vertex pair, sorted by
// (smaller, larger) vertex and then by corner: a counting sort by the
// smaller vertex (stable, so corners stay in order), then each bucket,
// about a vertex degree long, sorted by the larger vertex.
KeyedCorners corners_by_edge(const std::vector<std::uint32_t>& indices, const std::vector<std::uint32_t>& offsets,
                             std::uint32_t n) {
  const auto num_corners = static_cast<std::uint32_t>(indices.size());
  KeyedCorners keyed(num_corners);
  std::vector<std::uint32_t> bucket_start(std::size_t{n} + 1, 0);
  for_each_corner(offsets,
                  [&](const Corner& c) { ++bucket_start[std::min(indices[c.at], indices[c.next]) + 1]; });
  for (std::uint32_t v = 0; v < n; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<std::uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
  for_each_corner(offsets, [&](const Corner& c) {
    const std::uint64_t a = indices[c.at], b = indices[c.next];
    keyed[fill[std::min(a, b)]++] = {(std::min(a, b) << 32) | std::max(a, b), c.at};
  });
  for (std::uint32_t v = 0; v < n; ++v)
    std::sort(keyed.begin() + bucket_start[v], keyed.begin() + bucket_start[v + 1]);
  return keyed;
}

// Every edge used by exactly two faces in opposite directions; returns the
// number of edges. Scan all groups first, then report by severity: a
// non-manifold edge explains the orientation and boundary symptoms it causes.
std::uint32_t check_edge_groups(const KeyedCorners& keyed, const std::vector<std::uint32_t>& indices,
                                const std::vector<std::uint32_t>& offsets) {
  const auto face_of = [&](std::uint32_t c) { return face_of_corner(offsets, c); };
  std::string non_manifold, inconsistent, boundary;
  std::uint32_t num_edges = 0;
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    const std::uint32_t c0 = keyed[i].second;
    // c0 runs from a to b, the other vertex of the pair.
    const auto smaller = static_cast<std::uint32_t>(keyed[i].first >> 32);
    const auto larger = static_cast<std::uint32_t>(keyed[i].first);
    const std::uint32_t a = indices[c0], b = a == smaller ? larger : smaller;
    if (j - i > 2) {
      if (non_manifold.empty()) {
        non_manifold = edge_name(a, b) + " is shared by " + std::to_string(j - i) + " faces (";
        for (std::size_t k = i; k < j && k < i + 6; ++k)
          non_manifold += (k == i ? "" : ", ") + str(face_of(keyed[k].second));
        non_manifold += (j - i > 6 ? ", ...)" : ")");
        non_manifold += ": non-manifold edge";
      }
    } else if (j - i == 2) {
      const std::uint32_t c1 = keyed[i + 1].second;
      if (indices[c1] == a && inconsistent.empty())
        inconsistent = edge_name(a, b) + " is used in the same direction " + str(a) + " -> " + str(b) +
                       " by faces " + str(face_of(c0)) + " and " + str(face_of(c1)) +
                       ": inconsistent orientation (flipped face?)";
    } else if (boundary.empty()) {
      boundary = edge_name(a, b) + " of face " + str(face_of(c0)) +
                 " has no opposite face: the surface is open (boundary edge)";
    }
    ++num_edges;
    i = j;
  }
  if (!non_manifold.empty()) fail(non_manifold);
  if (!inconsistent.empty()) fail(inconsistent);
  if (!boundary.empty()) fail(boundary);
  return num_edges;
}

// The connectivity arrays of the mesh (see Mesh's members), and the number of
// halfedges leaving each vertex.
struct Connectivity {
  template <class T>
  using Array = detail::KeptVector<T>;

  explicit Connectivity(const std::shared_ptr<detail::ResultSlab>& slab)
      : vertex_he(Array<HalfedgeId>::allocator_type(slab)),
        he_to(Array<VertexId>::allocator_type(slab)),
        he_next(Array<HalfedgeId>::allocator_type(slab)),
        he_prev(Array<HalfedgeId>::allocator_type(slab)),
        he_face(Array<FaceId>::allocator_type(slab)),
        face_he(Array<HalfedgeId>::allocator_type(slab)) {}

  Array<HalfedgeId> vertex_he;
  Array<VertexId> he_to;
  Array<HalfedgeId> he_next;
  Array<HalfedgeId> he_prev;
  Array<FaceId> he_face;
  Array<HalfedgeId> face_he;
  std::vector<std::uint32_t> out_degree;
};

// Edge e's corners are keyed[2e] and keyed[2e + 1]; halfedge 2e runs from the
// smaller to the larger vertex.
Connectivity link_halfedges(const PolygonSoup& soup, const KeyedCorners& keyed, std::uint32_t num_edges,
                            std::uint32_t n, const std::shared_ptr<detail::ResultSlab>& slab) {
  const auto& indices = soup.face_indices;
  const auto& offsets = soup.face_offsets;
  const auto num_corners = static_cast<std::uint32_t>(indices.size());
  const auto num_faces = static_cast<std::uint32_t>(offsets.size() - 1);
  detail::ScratchVector<HalfedgeId> corner_he(num_corners);  // huge pages: fresh memory at every build
  for (std::uint32_t e = 0; e < num_edges; ++e) {
    for (std::uint32_t k = 0; k < 2; ++k) {
      const auto [key, c] = keyed[2 * e + k];
      const bool ascending = indices[c] == static_cast<std::uint32_t>(key >> 32);  // from the smaller vertex
      corner_he[c] = HalfedgeId(2 * e + (ascending ? 0u : 1u));
    }
  }
  Connectivity m(slab);
  m.he_to.resize(num_corners);
  m.he_next.resize(num_corners);
  m.he_prev.resize(num_corners);
  m.he_face.resize(num_corners);
  for_each_corner(offsets, [&](const Corner& c) {
    const std::uint32_t h = corner_he[c.at].index();
    m.he_to[h] = VertexId(indices[c.next]);
    m.he_next[h] = corner_he[c.next];
    m.he_prev[h] = corner_he[c.previous];
    m.he_face[h] = FaceId(c.face);
  });
  m.face_he.resize(num_faces);
  for (std::uint32_t f = 0; f < num_faces; ++f) m.face_he[f] = corner_he[soup.face_offsets[f]];
  m.vertex_he.assign(n, HalfedgeId());
  m.out_degree.assign(n, 0);
  for (std::uint32_t h = 0; h < num_corners; ++h) {
    const std::uint32_t v = m.he_to[h ^ 1u].index();  // from(h)
    if (!m.vertex_he[v].is_valid()) m.vertex_he[v] = HalfedgeId(h);
    ++m.out_degree[v];
  }
  return m;
}

// Manifold vertices: the fan around v, followed with twin(prev(h)), must
// reach every halfedge leaving v. (Each step is a permutation of the
// halfedges leaving v, so the walk always returns to its start.)
void check_manifold_vertices(const Mesh& m, const std::vector<std::uint32_t>& out_degree) {
  for (VertexId v : m.vertices()) {
    const HalfedgeId start = m.halfedge(v);
    HalfedgeId h = start;
    std::uint32_t len = 0;
    do {
      ++len;
      h = Mesh::twin(m.prev(h));
    } while (h != start && len <= out_degree[v.index()]);
    if (len != out_degree[v.index()])
      fail("vertex " + str(v.index()) + ": its faces form more than one fan (non-manifold vertex)");
  }
}

}  // namespace

std::uint32_t Mesh::degree(FaceId f) const noexcept {
  std::uint32_t n = 0;
  HalfedgeId start = face_he_[f.index()];
  HalfedgeId h = start;
  do {
    ++n;
    h = he_next_[h.index()];
  } while (h != start && n <= num_halfedges());
  return n;
}

namespace {

Mesh build(PolygonSoup soup, bool check_points, std::size_t num_points,
           std::shared_ptr<const detail::PackedVectors> packed, const std::shared_ptr<detail::ResultSlab>& slab) {
  check_soup_shape(soup, num_points);
  const auto n = static_cast<std::uint32_t>(num_points);
  check_faces(soup, n);
  if (check_points) {
    canonicalize_points(soup.points);
    check_distinct_points(soup.points);
  }
  const KeyedCorners keyed = corners_by_edge(soup.face_indices, soup.face_offsets, n);
  const std::uint32_t num_edges = check_edge_groups(keyed, soup.face_indices, soup.face_offsets);
  Connectivity c = link_halfedges(soup, keyed, num_edges, n, slab);

  auto storage = std::make_shared<MeshAccess::Storage>();
  storage->positions = std::move(soup.points);
  storage->packed_positions = std::move(packed);
  storage->vertex_he = std::move(c.vertex_he);
  storage->he_to = std::move(c.he_to);
  storage->he_next = std::move(c.he_next);
  storage->he_prev = std::move(c.he_prev);
  storage->he_face = std::move(c.he_face);
  storage->face_he = std::move(c.face_he);
  Mesh m = MeshAccess::view(std::move(storage));
  check_manifold_vertices(m, c.out_degree);
  return m;
}

// m's connectivity with the given positions; no checks.
std::shared_ptr<MeshAccess::Storage> same_connectivity(const Mesh& m, std::vector<Vec3> positions) {
  auto storage = std::make_shared<MeshAccess::Storage>();
  storage->positions = std::move(positions);
  if (const MeshAccess::Storage* s = MeshAccess::storage(m)) {
    storage->vertex_he = s->vertex_he;
    storage->he_to = s->he_to;
    storage->he_next = s->he_next;
    storage->he_prev = s->he_prev;
    storage->he_face = s->he_face;
    storage->face_he = s->face_he;
  }
  return storage;
}

}  // namespace

Mesh Mesh::from_soup(PolygonSoup soup) {
  const std::size_t n = soup.points.size();
  return build(std::move(soup), true, n, nullptr, nullptr);
}

Mesh MeshAccess::from_distinct_points(PolygonSoup soup) {
  const std::size_t n = soup.points.size();
  return build(std::move(soup), false, n, nullptr, nullptr);
}

Mesh MeshAccess::from_distinct_points(PolygonSoup faces, std::shared_ptr<const detail::PackedVectors> positions,
                                      const std::shared_ptr<detail::ResultSlab>& slab) {
  if (!faces.points.empty())
    throw Error(ErrorCategory::invalid_argument, "from_soup: packed positions come with a soup without points");
  const std::size_t n = positions->size();
  return build(std::move(faces), false, n, std::move(positions), slab);
}

const std::vector<Vec3>& Mesh::made_positions() const {
  static const std::vector<Vec3> none;  // an empty mesh has no positions
  if (storage_ == nullptr || storage_->packed_positions == nullptr) return none;
  return storage_->packed_positions->vectors();
}

namespace {

// Every stored reference in range, and next, prev, face and to consistent.
void check_halfedge_links(const Mesh& m) {
  const std::uint32_t H = m.num_halfedges(), V = m.num_vertices(), F = m.num_faces();
  for (std::uint32_t i = 0; i < H; ++i) {
    const HalfedgeId h(i);
    if (m.to(h).index() >= V) fail("validate: halfedge " + str(i) + " points to an invalid vertex");
    if (m.next(h).index() >= H || m.prev(h).index() >= H)
      fail("validate: halfedge " + str(i) + " has an invalid next or prev");
    if (m.face(h).index() >= F) fail("validate: halfedge " + str(i) + " has no valid face (open surface)");
  }
  for (std::uint32_t i = 0; i < H; ++i) {
    const HalfedgeId h(i);
    if (m.prev(m.next(h)) != h || m.next(m.prev(h)) != h)
      fail("validate: halfedge " + str(i) + ": next and prev disagree");
    if (m.face(m.next(h)) != m.face(h))
      fail("validate: halfedge " + str(i) + " and its next lie in different faces");
    if (m.from(m.next(h)) != m.to(h))
      fail("validate: halfedge " + str(i) + ": next does not start where it ends");
    if (m.from(h) == m.to(h))
      fail("validate: halfedge " + str(i) + " is a loop at vertex " + str(m.to(h).index()));
  }
}

// Faces: since next is a permutation that keeps the face, the face cycles
// cover every halfedge exactly once iff their lengths sum to H.
void check_face_cycles(const Mesh& m) {
  const std::uint32_t H = m.num_halfedges(), F = m.num_faces();
  std::vector<std::uint32_t> stamp(m.num_vertices(), no_index);
  std::uint64_t total = 0;
  for (std::uint32_t f = 0; f < F; ++f) {
    const HalfedgeId start = m.halfedge(FaceId(f));
    if (start.index() >= H || m.face(start) != FaceId(f))
      fail("validate: face " + str(f) + " has an invalid stored halfedge");
    HalfedgeId h = start;
    std::uint32_t len = 0;
    do {
      const std::uint32_t v = m.to(h).index();
      if (stamp[v] == f) fail("validate: face " + str(f) + " visits vertex " + str(v) + " twice");
      stamp[v] = f;
      ++len;
      h = m.next(h);
    } while (h != start && len <= H);
    if (h != start) fail("validate: face " + str(f) + " has no closed cycle");
    if (len < 3) fail("validate: face " + str(f) + " has fewer than 3 halfedges");
    total += len;
  }
  if (total != H) fail("validate: some face has more than one halfedge cycle");
}

// Vertex fans, likewise: twin(prev(.)) permutes the halfedges leaving a vertex.
void check_vertex_fans(const Mesh& m) {
  const std::uint32_t H = m.num_halfedges(), V = m.num_vertices();
  std::uint64_t total = 0;
  for (std::uint32_t v = 0; v < V; ++v) {
    const HalfedgeId start = m.halfedge(VertexId(v));
    if (start.index() >= H || m.from(start) != VertexId(v))
      fail("validate: vertex " + str(v) + " has an invalid stored halfedge (unreferenced vertex?)");
    HalfedgeId h = start;
    std::uint32_t len = 0;
    do {
      ++len;
      h = Mesh::twin(m.prev(h));
    } while (h != start && len <= H);
    if (h != start) fail("validate: the fan of vertex " + str(v) + " is not closed");
    total += len;
  }
  if (total != H) fail("validate: some vertex has more than one fan (non-manifold vertex)");
}

// No two edges between the same pair of vertices.
void check_distinct_edges(const Mesh& m) {
  std::vector<std::uint64_t> keys(m.num_edges());
  for (std::uint32_t e = 0; e < m.num_edges(); ++e) {
    const std::uint64_t a = m.to(HalfedgeId(2 * e)).index(), b = m.to(HalfedgeId(2 * e + 1)).index();
    keys[e] = (std::min(a, b) << 32) | std::max(a, b);
  }
  std::sort(keys.begin(), keys.end());
  auto dup = std::adjacent_find(keys.begin(), keys.end());
  if (dup != keys.end())
    fail("validate: " + edge_name(static_cast<std::uint32_t>(*dup >> 32), static_cast<std::uint32_t>(*dup)) +
         " appears more than once");
}

}  // namespace

void Mesh::validate() const {
  static const Storage none;
  const Storage& s = storage_ != nullptr ? *storage_ : none;
  const std::size_t nh = s.he_to.size();
  if (nh % 2 != 0 || s.he_next.size() != nh || s.he_prev.size() != nh || s.he_face.size() != nh)
    fail("validate: halfedge arrays have inconsistent sizes");
  const std::size_t num_points =
      s.packed_positions == nullptr ? s.positions.size() : s.packed_positions->size();
  if (s.vertex_he.size() != num_points) fail("validate: vertex arrays have inconsistent sizes");
  if (nh >= no_index || num_points >= no_index || s.face_he.size() >= no_index)
    fail("validate: element counts exceed 32-bit handles");
  if (num_vertices() == 0 || num_faces() == 0) fail("validate: empty mesh");
  check_halfedge_links(*this);
  check_face_cycles(*this);
  check_vertex_fans(*this);
  check_distinct_edges(*this);
}

PolygonSoup Mesh::to_soup() const {
  detail::FaceLists faces = detail::face_lists(*this);
  PolygonSoup soup;
  soup.points = positions();
  soup.face_offsets = std::move(faces.offsets);
  soup.face_indices = std::move(faces.indices);
  return soup;
}

// The count is read off the connectivity: the positions may be this mesh's
// own, moved out (from_soup's result takes them over).
Mesh MeshAccess::with_faces_from_smallest_vertex(const Mesh& m, std::vector<Vec3> positions) {
  if (positions.size() != m.num_vertices())
    throw Error(ErrorCategory::invalid_argument, "with_faces_from_smallest_vertex: got " +
                                                     std::to_string(positions.size()) + " positions for " +
                                                     std::to_string(m.num_vertices()) + " vertices");
  const std::shared_ptr<MeshAccess::Storage> storage = same_connectivity(m, std::move(positions));
  for (std::size_t f = 0; f < storage->face_he.size(); ++f) {
    HalfedgeId smallest = storage->face_he[f];
    for (HalfedgeId h : m.face_halfedges(FaceId(static_cast<std::uint32_t>(f))))
      if (m.from(h) < m.from(smallest)) smallest = h;
    storage->face_he[f] = smallest;
  }
  return view(storage);
}

Mesh Mesh::with_positions(std::vector<Vec3> positions) const {
  if (positions.size() != num_vertices())
    throw Error(ErrorCategory::invalid_argument, "with_positions: got " + std::to_string(positions.size()) +
                                                     " positions for " + std::to_string(num_vertices()) +
                                                     " vertices");
  return MeshAccess::view(same_connectivity(*this, std::move(positions)));
}

}  // namespace cvms
