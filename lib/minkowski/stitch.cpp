// SPDX-License-Identifier: MIT
// Facets of A + B from features of A and B, glued by vertex pair (paper
// Section 4.3; shared with the slope-diagram algorithm of Section 5.2).
#include "stitch.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <latch>
#include <numeric>
#include <limits>
#include <span>
#include <system_error>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/planar_sum.hpp"
#include "dyadic.hpp"
#include "error_bounds.hpp"
#include "first_use.hpp"
#include "polyhedron_builder.hpp"
#include "prefetch_exact.hpp"
#include "scaled_points.hpp"
#include "small_direction.hpp"
#include "two_word_scaled.hpp"
#include "word_scaled.hpp"
#include "worker.hpp"

namespace cvms::detail {
namespace {

// Planar sums are computed in 2D by dropping one coordinate. Projection along
// a coordinate axis not parallel to the plane is an affine bijection from the
// plane onto the coordinate plane; it is linear on R^3 (so it commutes with
// +), preserves convexity, parallelism and collinearity exactly, and maps
// distinct vertices to distinct points, so the index pairs of the planar sum
// are exactly those of the 3D sum. Every point involved lies in one of two
// parallel planes with normal n, and the projection of the sum of the two
// sets is the sum of the projections.
//
// Orientation: the signed area of the projection onto the coordinates
// (k+1, k+2) (cyclic, right-handed) of a polygon counterclockwise about n is
// the polygon's area times n_k / |n|. Keeping (k+1, k+2) when n_k > 0 and
// swapping them when n_k < 0 therefore keeps counterclockwise polygons
// counterclockwise. We drop the axis of the largest |n_k| (any nonzero n_k
// would do; the largest keeps the projected polygons well shaped for the
// floating-point filters).
struct Projection {
  int u;
  int v;
};

Projection projection_along(const Vec3& n) {
  int k = 0;
  if (cmp(abs(n.y), abs(n[k])) > 0) k = 1;
  if (cmp(abs(n.z), abs(n[k])) > 0) k = 2;
  int u = (k + 1) % 3;
  int v = (k + 2) % 3;
  if (sgn(n[k]) < 0) std::swap(u, v);
  return {u, v};
}

// out = the projection of p. Assigning into a reused Vec2 keeps its limbs,
// where constructing one would allocate four blocks per point.
void project_into(const Vec3& p, Projection pr, Vec2& out) {
  out.x = p[pr.u];
  out.y = p[pr.v];
}

// The projections of the given vertices as a prefix of scratch, which only
// grows, so that its rationals are reused from one planar sum to the next.
std::span<const Vec2> project_all(const ConvexPolyhedron& poly, std::span<const VertexId> vertices,
                                  Projection pr, std::vector<Vec2>& scratch) {
  if (scratch.size() < vertices.size()) scratch.resize(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) project_into(poly.vertex(vertices[k]), pr, scratch[k]);
  return {scratch.data(), vertices.size()};
}

// out = primitive_direction(cross(u, v)) for integer vectors u, v: the
// cross product and one gcd in integers (no rational canonicalisation).
void primitive_cross(const Vec3& u, const Vec3& v, Vec3& out) {
  const mpz_class* a[3] = {&u.x.get_num(), &u.y.get_num(), &u.z.get_num()};
  const mpz_class* b[3] = {&v.x.get_num(), &v.y.get_num(), &v.z.get_num()};
  mpz_class c[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpz_mul(c[i].get_mpz_t(), a[j]->get_mpz_t(), b[k]->get_mpz_t());
    mpz_submul(c[i].get_mpz_t(), a[k]->get_mpz_t(), b[j]->get_mpz_t());
  }
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), c[0].get_mpz_t(), c[1].get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c[2].get_mpz_t());
  for (int i = 0; i < 3; ++i) {
    mpz_divexact(mpq_numref(out[i].get_mpq_t()), c[i].get_mpz_t(), g.get_mpz_t());
    mpz_set_ui(mpq_denref(out[i].get_mpq_t()), 1);
  }
}

// Integer directions of the edges of one operand that edge facets use,
// each computed once (many edge facets share an edge), indexed by edge; the
// direction is that of the edge's even halfedge. Machine integers when the
// endpoints are doubles, or fractions whose common denominator and scaled
// numerators fit machine words (decimals as files hold them), rationals
// otherwise. Every form is a positive multiple of the same edge vector, so
// the primitive normal made from it is the same integer vector.
class EdgeDirections {
 public:
  explicit EdgeDirections(const ConvexPolyhedron& p) : p_(p), state_(p.num_edges(), State::unknown) {}

  // The small direction of h's edge, or nullptr if it has none.
  const SmallDirection* small(HalfedgeId h) {
    const std::uint32_t e = Mesh::edge(h).index();
    if (state_[e] == State::unknown) {
      if (!small_) small_.emplace(state_.size());  // written before read: no pass zeroes it
      const auto [from, to] = end_approximations(Mesh::edge(h));
      std::optional<SmallDirection> d = small_integer_direction(*from, *to);
      if (!d && !exactly_doubles(*from, *to)) d = fraction_direction(Mesh::edge(h));
      state_[e] = d ? State::small : State::general;
      if (d) (*small_)[e] = *d;
    }
    return state_[e] == State::small ? &(*small_)[e] : nullptr;
  }

  // Fetching ahead (prefetch_exact.hpp): a direction not yet known reads its
  // edge's ends through the mesh and then their approximations, two
  // dependent misses in the order the search met the edges (unfetched, about
  // a tenth of Sphere6 + rot. Sphere6); a known one is read from its cache.
  // fetch_ends `far` facets ahead; `near` ones ahead, once the ends have
  // arrived, the loop fetches what small(h) will read, at most an
  // ApproxVec3 from each address (a null one is nothing). The loop does
  // the fetching itself: GCC drops a void helper's prefetches.
  void fetch_ends(HalfedgeId h) const noexcept {
    __builtin_prefetch(&state_[Mesh::edge(h).index()]);
    __builtin_prefetch(MeshAccess::halfedge_targets(p_.mesh()) + Mesh::halfedge(Mesh::edge(h)).index());
  }
  [[nodiscard]] std::array<const void*, 2> read_by_small(HalfedgeId h) const noexcept {
    const EdgeId e = Mesh::edge(h);
    switch (state_[e.index()]) {
      case State::small:
        return {&(*small_)[e.index()], nullptr};
      case State::general:
        return {nullptr, nullptr};
      case State::unknown:
        break;
    }
    const auto [from, to] = end_approximations(e);
    return {from, to};
  }

  // The approximations of the ends of e's even halfedge, from and to: what
  // an unknown direction is made of.
  [[nodiscard]] std::array<const ApproxVec3*, 2> end_approximations(EdgeId e) const noexcept {
    const Mesh& m = p_.mesh();
    const HalfedgeId even = Mesh::halfedge(e);
    return {&detail::vertex_approx(p_, m.from(even)), &detail::vertex_approx(p_, m.to(even))};
  }

  // Ends that are doubles (no approximation error) that small_integer_direction
  // refused have exponents too far apart for the fraction path as well.
  [[nodiscard]] static bool exactly_doubles(const ApproxVec3& from, const ApproxVec3& to) noexcept {
    return from.x.error == 0.0 && from.y.error == 0.0 && from.z.error == 0.0 && to.x.error == 0.0 &&
           to.y.error == 0.0 && to.z.error == 0.0;
  }

  // The direction of e's even halfedge from the exact ends, as fractions over
  // their common denominator, when that fits machine words: the difference
  // of the ends' integers over the operand's common denominator
  // (word_scaled.hpp, made once per operand), or of its two-word integers
  // divided by their common factors (two_word_scaled.hpp, small_multiple),
  // else over the two ends'.
  [[nodiscard]] std::optional<SmallDirection> fraction_direction(EdgeId e) {
    const Mesh& m = p_.mesh();
    const HalfedgeId even = Mesh::halfedge(e);
    if (!scaled_asked_) {
      scaled_ = PolyhedronAccess::scaled_vertices(p_);
      scaled_asked_ = true;
    }
    if (scaled_ != nullptr) {
      const std::size_t from = m.from(even).index(), to = m.to(even).index();
      SmallDirection d{};
      for (int axis = 0; axis < 3; ++axis)
        d.c[static_cast<std::size_t>(axis)] = scaled_->at(to, axis) - scaled_->at(from, axis);  // below 2^62
      if (d.c[0] == 0 && d.c[1] == 0 && d.c[2] == 0) return std::nullopt;
      return d;
    }
    if (two_word() != nullptr) {
      const auto [x, y, z] = two_word_difference(e);
      return small_multiple(x, y, z);
    }
    return small_fraction_direction(p_.vertex(m.from(even)), p_.vertex(m.to(even)));
  }

  // p_'s two-word integers (two_word_scaled.hpp, made once per operand), or null.
  const TwoWordScaledPoints* two_word() {
    if (!two_word_asked_) {
      two_word_ = PolyhedronAccess::two_word_scaled_vertices(p_);
      two_word_asked_ = true;
    }
    return two_word_;
  }
  // The difference of the ends of e's even halfedge in two_word()'s
  // integers (each below 2^124, so the difference below 2^125: no overflow).
  [[nodiscard]] std::array<SmallNormal::Int128, 3> two_word_difference(EdgeId e) const {
    const Mesh& m = p_.mesh();
    const HalfedgeId even = Mesh::halfedge(e);
    const std::size_t from = m.from(even).index(), to = m.to(even).index();
    return {two_word_->at(to, 0) - two_word_->at(from, 0), two_word_->at(to, 1) - two_word_->at(from, 1),
            two_word_->at(to, 2) - two_word_->at(from, 2)};
  }

  // The direction of h's edge as rationals (rarely needed: only when the
  // other edge of an edge facet has no small direction).
  const Vec3& general(HalfedgeId h) {
    const std::uint32_t e = Mesh::edge(h).index();
    auto [it, inserted] = general_.try_emplace(e);
    if (inserted) {
      const SmallDirection* s = small(h);
      if (s != nullptr) {
        it->second = s->to_vec3();
      } else if (scaled_ == nullptr && two_word() != nullptr) {
        // The same primitive vector, without rationals; nonzero: an edge's ends differ.
        const auto [x, y, z] = two_word_difference(Mesh::edge(h));
        primitive_vector(x, y, z).assign_to(it->second);
      } else {
        it->second = primitive_direction(p_.edge_vector(Mesh::halfedge(Mesh::edge(h))));
      }
    }
    return it->second;
  }

 private:
  enum class State : std::uint8_t { unknown, small, general };
  const ConvexPolyhedron& p_;
  const WordScaledPoints* scaled_ = nullptr;  // p_'s, once asked for
  bool scaled_asked_ = false;
  const TwoWordScaledPoints* two_word_ = nullptr;  // p_'s, once asked for (when scaled_ is null)
  bool two_word_asked_ = false;
  std::vector<State> state_;
  // On huge pages when large: fresh memory at every sum (huge_page_blocks.hpp).
  std::optional<HugePageArray<SmallDirection, BlockLife::scratch>> small_;
  std::unordered_map<std::uint32_t, Vec3> general_;
};

// Approx::of(x + y) from the approximations of x and y when both are exact
// doubles, without converting the exact sum back from GMP: TwoSum (Knuth)
// gives the nearest double s and the exact rounding error r = x + y - s;
// Approx::of truncates toward zero, which is s itself when r is zero or
// points away from zero, and the next double toward zero otherwise. The
// error bound is Approx::of's, so the cached value is the same either way
// (error_bounds.hpp says why this sum is not bounded as CHMS's sums are).
// exact_sum() gives the exact sum, asked for only when x or y is not exact
// or their double sum overflows.
template <typename ExactSum>
Approx approx_sum(const Approx& x, const Approx& y, ExactSum&& exact_sum) {
  if (x.error == 0.0 && y.error == 0.0) {
    const double s = x.value + y.value;
    if (std::isfinite(s)) {
      const double y_part = s - x.value;
      const double r = (x.value - (s - y_part)) + (y.value - y_part);
      if (r == 0.0) return {s, 0.0};
      const double truncated = (r > 0.0) == (s > 0.0) ? s : std::nextafter(s, 0.0);
      return {truncated, filtered::truncation_error(truncated)};
    }
  }
  return Approx::of(exact_sum());
}

Approx& axis_of(ApproxVec3& v, int axis) noexcept { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }
const Approx& axis_of(const ApproxVec3& v, int axis) noexcept { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

// How many vertices a sum with these facets has: a convex polyhedron is a
// sphere, so V = E - F + 2 by Euler's formula, and every edge has two
// corners. Exact for a correct sum; only a reservation (never a bound that
// is relied on) should a caller break the precondition.
std::size_t euler_vertex_count(const PolygonSoup& faces) noexcept {
  const std::size_t edges = faces.face_offsets.back() / 2;
  const std::size_t facets = faces.face_offsets.size() - 1;
  return edges + 2 > facets ? edges + 2 - facets : 0;
}

// A dense pair -> output-index table is used when it is not much larger than
// the output itself; otherwise the pairs are numbered by sorting.
constexpr std::uint64_t dense_table_limit = 1u << 16;

}  // namespace

SumFacetBuilder::SumFacetBuilder(const ConvexPolyhedron& a, const ConvexPolyhedron& b) : a_(a), b_(b) {}

void SumFacetBuilder::add_facet_plus_vertex(Operand which, FaceId f, VertexId v) {
  const Mesh& m = operand(which).mesh();
  for (HalfedgeId h : m.face_halfedges(f)) push(which, m.from(h), v);
  close_facet(facet_normal(which, f));
}

void SumFacetBuilder::add_facet_plus_edge(Operand which, FaceId f, VertexId v0, VertexId v1) {
  const VertexId other[2] = {v0, v1};
  add_planar_sum(which, f, other);
}

void SumFacetBuilder::add_facet_plus_facet(FaceId fa, FaceId fb) {
  const Mesh& mb = b_.mesh();
  other_vertices_.clear();
  for (HalfedgeId h : mb.face_halfedges(fb)) other_vertices_.push_back(mb.from(h));
  add_planar_sum(Operand::a, fa, other_vertices_);
}

void SumFacetBuilder::add_planar_sum(Operand which, FaceId f, std::span<const VertexId> other) {
  const ConvexPolyhedron& own = operand(which);
  const ConvexPolyhedron& oth = operand(which == Operand::a ? Operand::b : Operand::a);
  const Projection pr = projection_along(own.normal(f));
  own_vertices_.clear();
  for (HalfedgeId h : own.mesh().face_halfedges(f)) own_vertices_.push_back(own.mesh().from(h));
  const std::span<const Vec2> own_points = project_all(own, own_vertices_, pr, own_points_);
  const std::span<const Vec2> other_points = project_all(oth, other, pr, other_points_);
  for (const auto& [i, j] : planar_sum_indices(own_points, other_points)) {
    push(which, own_vertices_[i], other[j]);
  }
  close_facet(facet_normal(which, f));
}

void SumFacetBuilder::add_edge_plus_edge(HalfedgeId ha, HalfedgeId hb, Sign orientation) {
  close_facet({orientation == Sign::positive ? NormalKind::edges_positive : NormalKind::edges_negative,
               ha.index(), hb.index()});
}

std::array<VertexPair, 4> SumFacetBuilder::edge_cycle(const NormalSource& source) const {
  const Mesh& ma = a_.mesh();
  const Mesh& mb = b_.mesh();
  const HalfedgeId ha(source.index), hb(source.other);
  const std::uint32_t ua = ma.from(ha).index();
  const std::uint32_t va = ma.to(ha).index();
  const std::uint32_t ub = mb.from(hb).index();
  const std::uint32_t vb = mb.to(hb).index();
  // The cycle ua+ub, va+ub, va+vb, ua+vb has edge vectors d_A, d_B, -d_A,
  // -d_B, hence normal cross(d_A, d_B); reversed, the opposite normal.
  if (source.kind == NormalKind::edges_positive) return {{{ua, ub}, {va, ub}, {va, vb}, {ua, vb}}};
  return {{{ua, vb}, {va, vb}, {va, ub}, {ua, ub}}};
}

std::vector<VertexPair> SumFacetBuilder::facet(std::size_t i) const {
  if (is_edge_facet(normals_[i])) {
    const std::array<VertexPair, 4> cycle = edge_cycle(normals_[i]);
    return {cycle.begin(), cycle.end()};
  }
  return {pairs_.data() + offsets_[i], pairs_.data() + offsets_[i + 1]};
}

std::vector<std::uint32_t> SumFacetBuilder::corner_offsets() const {
  std::vector<std::uint32_t> offsets;
  offsets.reserve(num_facets() + 1);
  offsets.push_back(0);
  for (std::size_t i = 0; i < num_facets(); ++i)
    offsets.push_back(offsets.back() + (is_edge_facet(normals_[i]) ? 4 : offsets_[i + 1] - offsets_[i]));
  return offsets;
}

void SumFacetBuilder::append(const SumFacetBuilder& other, std::size_t begin, std::size_t end) {
  const std::uint32_t first = other.offsets_[begin];
  const std::uint32_t base = static_cast<std::uint32_t>(pairs_.size()) - first;
  pairs_.append(other.pairs_.begin() + first, other.pairs_.begin() + other.offsets_[end]);
  for (std::size_t i = begin + 1; i <= end; ++i) offsets_.push_back(base + other.offsets_[i]);
  normals_.append(other.normals_.begin() + begin, other.normals_.begin() + end);
}

PolygonSoup SumFacetBuilder::soup() const { return soup(nullptr, nullptr); }

template <typename PairAt>
void SumFacetBuilder::prefetch_operand_vertices(std::size_t j, std::size_t end, PairAt&& pair_at) const {
  // The operands' exact coordinates and their approximations, visited out
  // of order: fetched ahead (prefetch_exact.hpp). The approximations' misses
  // were two fifths of write_packed_vertex.
  if (j + prefetch_far < end) {
    const VertexPair ahead = pair_at(j + prefetch_far);
    prefetch_structs(a_.vertex(VertexId(ahead.a)));
    prefetch_structs(b_.vertex(VertexId(ahead.b)));
    prefetch_bytes(&detail::vertex_approx(a_, VertexId(ahead.a)), sizeof(ApproxVec3));
    prefetch_bytes(&detail::vertex_approx(b_, VertexId(ahead.b)), sizeof(ApproxVec3));
  }
  if (j + prefetch_near < end) {
    const VertexPair ahead = pair_at(j + prefetch_near);
    prefetch_limbs(a_.vertex(VertexId(ahead.a)));
    prefetch_limbs(b_.vertex(VertexId(ahead.b)));
  }
}

template <typename NewVertex>
void SumFacetBuilder::number_corners(PolygonSoup& soup, bool prefetch_operands,
                                     NewVertex&& new_vertex) const {
  const std::uint64_t nb = b_.num_vertices();
  const std::uint64_t table_size = std::uint64_t{a_.num_vertices()} * nb;
  const std::size_t corners = soup.face_offsets.back();
  if (table_size <= dense_table_limit || table_size <= 8 * std::uint64_t{corners}) {
    constexpr std::uint32_t unset = ~std::uint32_t{0};
    std::vector<std::uint32_t> index(table_size, unset);
    soup.face_indices.reserve(corners);
    for_each_corner([&](const VertexPair& p) {
      std::uint32_t& slot = index[p.a * nb + p.b];
      if (slot == unset) slot = new_vertex(p);
      soup.face_indices.push_back(slot);
    });
    return;
  }
  // Sparse: numbered by sorting, not hashing (std::hash of an integer is
  // the identity, so keys j * nb + v that an input lines up modulo the
  // bucket count would make a hash map quadratic).
  ScratchVector<std::uint64_t> keys;  // on huge pages: fresh memory at every sum (huge_page_blocks.hpp)
  keys.reserve(corners);
  for_each_corner([&](const VertexPair& p) { keys.push_back(p.a * nb + p.b); });
  detail::FirstUse numbered = detail::first_use(keys, std::less<>{});
  const auto pair_of = [&](std::size_t j) -> VertexPair {
    const std::uint64_t key = keys[numbered.first[j]];
    return {static_cast<std::uint32_t>(key / nb), static_cast<std::uint32_t>(key % nb)};
  };
  const std::size_t vertices = numbered.first.size();
  for (std::size_t j = 0; j < vertices; ++j) {
    if (prefetch_operands) prefetch_operand_vertices(j, vertices, pair_of);
    new_vertex(pair_of(j));
  }
  soup.face_indices = std::move(numbered.index);  // one number per corner, in corner order
}

PolygonSoup SumFacetBuilder::faces_without_points() const {
  PolygonSoup soup;
  soup.face_offsets = corner_offsets();  // number_corners fills face_indices
  return soup;
}

void SumFacetBuilder::write_vertex(const VertexPair& p, const VertexOutput& out, std::size_t j,
                                   Vec3& scratch) const {
  const VertexId va(p.a), vb(p.b);
  Vec3& point = out.points[j];
  const Vec3 &pa = a_.vertex(va), &pb = b_.vertex(vb);
  for (int i = 0; i < 3; ++i) {
    if (out.limbs != nullptr) {
      store_sum(*out.limbs, point[i], pa[i], pb[i], scratch[i]);
    } else {
      add_into(point[i], pa[i], pb[i]);
    }
  }
  if (out.approx != nullptr) {
    const ApproxVec3 &xa = detail::vertex_approx(a_, va), &xb = detail::vertex_approx(b_, vb);
    for (int i = 0; i < 3; ++i)
      axis_of(out.approx[j], i) = approx_sum(axis_of(xa, i), axis_of(xb, i), [&]() -> const Rational& { return point[i]; });
  }
}

void SumFacetBuilder::write_vertices(std::span<const VertexPair> pairs, std::size_t begin, std::size_t end,
                                     const VertexOutput& out, Vec3& scratch) const {
  for (std::size_t j = begin; j < end; ++j) {
    prefetch_operand_vertices(j, end, [&](std::size_t k) { return pairs[k]; });
    write_vertex(pairs[j], out, j, scratch);
  }
}

bool SumFacetBuilder::write_packed_vertex(const VertexPair& p, const PackedOutput& out, std::size_t j,
                                          Vec3& scratch) const {
  const VertexId va(p.a), vb(p.b);
  const Vec3 &pa = a_.vertex(va), &pb = b_.vertex(vb);
  const ApproxVec3 &xa = detail::vertex_approx(a_, va), &xb = detail::vertex_approx(b_, vb);
  for (int i = 0; i < 3; ++i) {
    PackedDyadic& coordinate = out.points->coordinate(j, i);
    if (const std::optional<FixedDyadic<2>> sum = fixed_sum(pa[i], pb[i])) {
      pack_dyadic(*sum, *out.limbs, coordinate);
    } else {
      add_into(scratch[i], pa[i], pb[i]);
      if (!pack_dyadic(scratch[i], *out.limbs, coordinate)) return false;
    }
    axis_of(out.approx[j], i) = approx_sum(axis_of(xa, i), axis_of(xb, i), [&]() -> const Rational& {
      unpack_dyadic(coordinate, scratch[i]);
      return scratch[i];
    });
  }
  return true;
}

bool SumFacetBuilder::write_packed_vertices(std::span<const VertexPair> pairs, std::size_t begin, std::size_t end,
                                            const PackedOutput& out, Vec3& scratch) const {
  for (std::size_t j = begin; j < end; ++j) {
    prefetch_operand_vertices(j, end, [&](std::size_t k) { return pairs[k]; });
    if (!write_packed_vertex(pairs[j], out, j, scratch)) return false;
  }
  return true;
}

namespace {

// Whether a few vertices spread over p are all doubles (exact
// approximations): what operands read from doubles show, and decimals do not.
bool looks_like_doubles(const ConvexPolyhedron& p) {
  constexpr std::size_t probes = 8;
  const std::size_t n = p.num_vertices();
  for (std::size_t k = 0; k < probes && k < n; ++k) {
    const ApproxVec3& x = detail::vertex_approx(p, VertexId(static_cast<std::uint32_t>(k * n / probes)));
    if (x.x.error != 0.0 || x.y.error != 0.0 || x.z.error != 0.0) return false;
  }
  return true;
}

}  // namespace

std::optional<SumFacetBuilder::ScaledSum> SumFacetBuilder::scaled_sum() const {
  if (looks_like_doubles(a_) && looks_like_doubles(b_)) return std::nullopt;
  const WordScaledPoints* sa = PolyhedronAccess::scaled_vertices(a_);
  const WordScaledPoints* sb = sa != nullptr ? PolyhedronAccess::scaled_vertices(b_) : nullptr;
  if (sb == nullptr) return two_word_scaled_sum();
  if (sa->dyadic() && sb->dyadic()) return std::nullopt;
  // L = (D_A / g) D_B < 2^126 for g = gcd(D_A, D_B); the factors are below 2^63.
  const std::uint64_t g = std::gcd(sa->denominator, sb->denominator);
  const std::uint64_t factor_a = sb->denominator / g, factor_b = sa->denominator / g;
  return ScaledSum{sa, sb, ScaledPoints::Uint128{sa->denominator} * factor_a, factor_a, factor_b};
}

std::optional<SumFacetBuilder::ScaledSum> SumFacetBuilder::two_word_scaled_sum() const {
  const TwoWordScaledPoints* wa = PolyhedronAccess::two_word_scaled_vertices(a_);
  const TwoWordScaledPoints* wb = wa != nullptr ? PolyhedronAccess::two_word_scaled_vertices(b_) : nullptr;
  if (wb == nullptr || (wa->dyadic() && wb->dyadic())) return std::nullopt;  // the packed dyadic path's
  const std::optional<TwoWordSum> fits = two_word_sum_fits(*wa, *wb);
  if (!fits) return std::nullopt;
  return ScaledSum{nullptr, nullptr, fits->denominator, 0, 0, wa, wb, fits->factor_a, fits->factor_b};
}

void SumFacetBuilder::write_scaled_vertex(const VertexPair& p, const ScaledSum& sum, ScaledPoints& points,
                                          ApproxVec3* approx, std::size_t j) const {
  using Int128 = ScaledPoints::Int128;
  if (sum.a == nullptr) {
    for (int i = 0; i < 3; ++i) {
      // |a| f_A + |b| f_B < 2^125 for the largest |a| and |b| (two_word_sum_fits).
      const Int128 n = sum.wide_a->at(p.a, i) * static_cast<Int128>(sum.wide_factor_a) +
                       sum.wide_b->at(p.b, i) * static_cast<Int128>(sum.wide_factor_b);
      points.numerator(j, i) = n;
      axis_of(approx[j], i) = points.approx(n);
    }
    return;
  }
  for (int i = 0; i < 3; ++i) {
    // Each term is below 2^61 2^63 = 2^124 in magnitude (word_scaled.hpp).
    const Int128 n =
        Int128{sum.a->at(p.a, i)} * Int128{sum.factor_a} + Int128{sum.b->at(p.b, i)} * Int128{sum.factor_b};
    points.numerator(j, i) = n;
    axis_of(approx[j], i) = points.approx(n);
  }
}

void SumFacetBuilder::write_scaled_vertices(std::span<const VertexPair> pairs, std::size_t begin, std::size_t end,
                                            const ScaledSum& sum, ScaledPoints& points, ApproxVec3* approx) const {
  for (std::size_t j = begin; j < end; ++j) {
    if (j + prefetch_far < end) {  // the pairs are met out of memory order
      const VertexPair& ahead = pairs[j + prefetch_far];
      if (sum.a != nullptr) {
        __builtin_prefetch(&sum.a->numerators[3 * std::size_t{ahead.a}]);
        __builtin_prefetch(&sum.b->numerators[3 * std::size_t{ahead.b}]);
      } else {
        __builtin_prefetch(&sum.wide_a->numerators[3 * std::size_t{ahead.a}]);
        __builtin_prefetch(&sum.wide_b->numerators[3 * std::size_t{ahead.b}]);
      }
    }
    write_scaled_vertex(pairs[j], sum, points, approx, j);
  }
}

Mesh SumFacetBuilder::scaled_mesh(PolygonSoup faces, VertexApproximations& approx,
                                  const std::shared_ptr<ResultSlab>& slab, const ScaledSum& sum) const {
  const std::size_t count = euler_vertex_count(faces);
  ScaledPoints points(sum.denominator, carving_from<ScaledPoints::Int128>(slab));
  points.reserve(count);
  approx.reserve(count);
  number_corners(faces, false, [&](const VertexPair& p) {
    const std::size_t j = points.append();
    approx.emplace_back();
    write_scaled_vertex(p, sum, points, approx.data(), j);
    return static_cast<std::uint32_t>(j);
  });
  return output_mesh(std::move(faces), std::make_shared<const PackedVectors>(std::move(points)), slab);
}

std::shared_ptr<ResultSlab> SumFacetBuilder::output_slab(const PolygonSoup& faces) const {
  const std::size_t vertices = euler_vertex_count(faces);
  SlabPlan plan;
  DyadicPoints::plan(plan, vertices);
  plan.add<ApproxVec3>(vertices);
  plan_output_mesh(plan, vertices, faces.face_offsets.back(), num_facets());
  return ResultSlab::make(plan);
}

std::optional<Mesh> SumFacetBuilder::packed_mesh(PolygonSoup faces, VertexApproximations& approx,
                                                 const std::shared_ptr<ResultSlab>& slab) const {
  if (const std::optional<ScaledSum> sum = scaled_sum()) return scaled_mesh(std::move(faces), approx, slab, *sum);
  const std::size_t count = euler_vertex_count(faces);
  DyadicPoints points(carving_from<PackedDyadic>(slab));
  points.reserve(count);
  approx.reserve(count);
  Vec3 scratch;  // for the sums that do not fit machine words
  bool dyadic = true;
  number_corners(faces, true, [&](const VertexPair& p) {
    const std::size_t j = points.append();
    approx.emplace_back();
    if (dyadic) dyadic = write_packed_vertex(p, {&points, approx.data(), &points.limbs()}, j, scratch);
    return static_cast<std::uint32_t>(j);
  });
  if (!dyadic) return std::nullopt;
  return output_mesh(std::move(faces), std::make_shared<const PackedVectors>(std::move(points)), slab);
}

PolygonSoup SumFacetBuilder::soup(VertexApproximations* approx, LimbArena* limbs) const {
  PolygonSoup soup = faces_without_points();
  soup.points.reserve(soup.face_offsets.back() / 3 + 1);  // each vertex is in at least three facets
  if (approx != nullptr) approx->reserve(soup.points.capacity());
  Vec3 scratch;  // reused by store_sum's general path
  number_corners(soup, true, [&](const VertexPair& p) {
    // Built in place: moving an mpq_class re-initialises the source, which allocates.
    soup.points.emplace_back();
    if (approx != nullptr) approx->emplace_back();
    const std::size_t j = soup.points.size() - 1;
    write_vertex(p, {soup.points.data(), approx != nullptr ? approx->data() : nullptr, limbs}, j, scratch);
    return static_cast<std::uint32_t>(j);
  });
  return soup;
}

// What one thread needs to write normals: its own lazy caches of edge
// directions, and reused scratch.
struct SumFacetBuilder::NormalScratch {
  NormalScratch(const SumFacetBuilder& builder, DyadicPoints& packed, LimbArena& arena)
      : directions_a(builder.a_), directions_b(builder.b_), normals(packed), limbs(arena) {}
  EdgeDirections directions_a;
  EdgeDirections directions_b;
  Vec3 normal;
  DyadicPoints& normals;  // where the normals go, packed
  LimbArena& limbs;       // where this thread's long numerators go
  // Packs normal i (an integer vector, which always packs).
  void pack(std::size_t i, const Vec3& exact) {
    if (!normals.pack(i, exact, limbs))
      throw Error(ErrorCategory::limit, "a facet normal of the sum does not fit 2^31 limbs");
  }
};

void SumFacetBuilder::write_normals(FacetPlanes& planes, std::size_t begin, std::size_t end,
                                    NormalScratch& scratch) const {
  for (std::size_t i = begin; i < end; ++i) {
    // Issued here, not in a void helper: prefetch_exact.hpp says why.
    if (i + prefetch_far < end && is_edge_facet(normals_[i + prefetch_far])) {
      const NormalSource& ahead = normals_[i + prefetch_far];
      scratch.directions_a.fetch_ends(HalfedgeId(ahead.index));
      scratch.directions_b.fetch_ends(HalfedgeId(ahead.other));
    }
    if (i + prefetch_near < end && is_edge_facet(normals_[i + prefetch_near])) {
      const NormalSource& ahead = normals_[i + prefetch_near];
      for (const auto& read : {scratch.directions_a.read_by_small(HalfedgeId(ahead.index)),
                               scratch.directions_b.read_by_small(HalfedgeId(ahead.other))})
        for (const void* at : read)
          if (at != nullptr) prefetch_bytes(at, sizeof(ApproxVec3));
    }
    write_normal(planes, i, scratch);
  }
}

void SumFacetBuilder::write_normal(FacetPlanes& planes, std::size_t i, NormalScratch& scratch) const {
  const NormalSource& source = normals_[i];
  switch (source.kind) {
    case NormalKind::facet_a:
    case NormalKind::facet_b: {
      // The operand's approximation is ApproxVec3::of of the same normal:
      // copied, not worked out again.
      const ConvexPolyhedron& p = source.kind == NormalKind::facet_a ? a_ : b_;
      const Vec3Ref operand_normal = detail::normal_ref(p, FaceId(source.index));
      planes.normal_approx[i] = operand_normal.approx;
      scratch.pack(i, operand_normal.exact);
      return;
    }
    case NormalKind::edges_positive:
    case NormalKind::edges_negative: {
      // The directions belong to the even halfedge of each edge.
      const HalfedgeId ha(source.index), hb(source.other);
      const SmallDirection* da = scratch.directions_a.small(ha);
      const SmallDirection* db = scratch.directions_b.small(hb);
      const bool flip =
          (source.kind == NormalKind::edges_negative) != ((ha.index() & 1u) != (hb.index() & 1u));
      if (da != nullptr && db != nullptr) {
        // Straight from 128-bit integers: no GMP value to copy.
        SmallNormal small = primitive_cross(*da, *db);
        if (flip) small.negate();
        planes.normal_approx[i] = small.approx();
        small.pack(scratch.limbs, scratch.normals, i);
        return;
      }
      primitive_cross(scratch.directions_a.general(ha), scratch.directions_b.general(hb), scratch.normal);
      if (flip)
        for (int k = 0; k < 3; ++k) mpq_neg(scratch.normal[k].get_mpq_t(), scratch.normal[k].get_mpq_t());
      break;
    }
  }
  planes.normal_approx[i] = ApproxVec3::of(scratch.normal);
  scratch.pack(i, scratch.normal);
}

ConvexPolyhedron SumFacetBuilder::build(unsigned threads, ProgressReporter* progress) const {
  ProgressReporter silent(nullptr);
  ProgressReporter& reporter = progress != nullptr ? *progress : silent;
  reporter.begin("sum: output", num_facets());
  ConvexPolyhedron result = threads > 1 ? build_on_two_threads(reporter) : build_on_one_thread(reporter);
  reporter.end();
  return result;
}

ConvexPolyhedron SumFacetBuilder::build_on_one_thread(ProgressReporter& progress) const {
  // The vertices and normals are packed, each keeping its long numerators'
  // limbs; only Vec3 vertices (the fallback) keep theirs in an arena the
  // result keeps.
  LimbArena limbs;
  MeshWithApprox output = mesh_with_points(&limbs);
  FacetPlanes planes;
  DyadicPoints& normals = size_packed_planes(planes, num_facets())->packed_for_writing();
  NormalScratch scratch(*this, normals, normals.limbs());
  // In chunks only to report between them: the normals are independent.
  const std::size_t chunk = progress.active() ? progress_chunk : num_facets();
  for (std::size_t begin = 0; begin < num_facets(); begin += chunk) {
    const std::size_t end = std::min(begin + chunk, num_facets());
    write_normals(planes, begin, end, scratch);
    progress.advance(end - begin);
  }
  return assemble(std::move(output.mesh), std::move(output.approx), std::move(planes), std::move(limbs));
}

Mesh SumFacetBuilder::build_mesh() const { return mesh_with_points(nullptr).mesh; }

SumFacetBuilder::MeshWithApprox SumFacetBuilder::mesh_with_points(LimbArena* limbs) const {
  PolygonSoup faces = faces_without_points();
  const std::shared_ptr<ResultSlab> slab = output_slab(faces);
  VertexApproximations vertex_approx(carving_from<ApproxVec3>(slab));
  std::optional<Mesh> mesh = packed_mesh(std::move(faces), vertex_approx, slab);
  if (!mesh) {  // inputs with other rationals than dyadic ones: Vec3s
    vertex_approx.clear();
    mesh = output_mesh(soup(&vertex_approx, limbs));
  }
  return {std::move(*mesh), std::move(vertex_approx)};
}

namespace {

// Counts a latch down once: when called, or else when destroyed, so that a
// thread that throws never leaves the other one waiting.
class CountDownOnce {
 public:
  explicit CountDownOnce(std::latch& latch) noexcept : latch_(&latch) {}
  CountDownOnce(const CountDownOnce&) = delete;
  CountDownOnce& operator=(const CountDownOnce&) = delete;
  ~CountDownOnce() { (*this)(); }
  void operator()() noexcept {
    if (latch_ != nullptr) latch_->count_down();
    latch_ = nullptr;
  }

 private:
  std::latch* latch_;
};

// Hands out [0, n) in chunks to whichever thread asks, until none is left
// or a thread gives up for all (after a failure, so that the other one
// takes no more work). Any split gives the same values. n may be set after
// construction, before any thread takes (the threads synchronise on that).
class ChunkCounter {
 public:
  explicit ChunkCounter(std::size_t chunk) noexcept : chunk_(chunk) {}
  void set_size(std::size_t n) noexcept { n_ = n; }
  template <typename Work>
  void take(Work&& work) {
    for (std::size_t begin = next_.fetch_add(chunk_); begin < n_; begin = next_.fetch_add(chunk_))
      work(begin, std::min(begin + chunk_, n_));
  }
  // Writes only the atomic counter, so that a thread may give up while the
  // other one still sets the size.
  void give_up() noexcept { next_ = none_left; }

 private:
  // Beyond every size, and far from overflowing fetch_add.
  static constexpr std::size_t none_left = std::numeric_limits<std::size_t>::max() / 2;
  std::size_t n_ = 0;
  std::size_t chunk_;
  std::atomic<std::size_t> next_{0};
};

}  // namespace

ConvexPolyhedron SumFacetBuilder::build_on_two_threads(ProgressReporter& progress) const {
  // Three parts: the numbering of the vertices with the mesh's topology
  // (this thread; it reads no coordinate), the facet normals (a worker
  // starts on them at once, into planes it sizes), and the vertices'
  // coordinates, packed into the mesh's points once the mesh stands. Both
  // threads take normals, then vertices, in chunks. Both are packed; each
  // thread keeps the long numerators it makes in arenas of its own, which
  // the packed normals and points then keep.
  const std::size_t facets = num_facets();
  PolygonSoup soup = faces_without_points();
  const std::shared_ptr<ResultSlab> slab = output_slab(soup);
  LimbArena limbs, worker_limbs, vertex_limbs, worker_vertex_limbs;
  FacetPlanes planes;
  std::shared_ptr<PackedVectors> packed_normals;
  ChunkCounter normals(256), vertices(512);
  normals.set_size(facets);
  // Sized (and `positions` made) by this thread before `meshed` is counted
  // down; after that the arrays' elements are written by both threads, in
  // disjoint chunks, and nothing is resized. `packed_normals` is made by the
  // worker before `sized` is counted down. Either may still be null after
  // its latch if the thread that makes it failed: the counters are given up
  // then, and nothing is taken.
  ScratchVector<VertexPair> pairs;  // by output vertex
  VertexApproximations vertex_approx(carving_from<ApproxVec3>(slab));
  std::shared_ptr<PackedVectors> positions;
  const std::optional<ScaledSum> scaled = scaled_sum();
  std::atomic<bool> not_dyadic{false};
  std::latch sized(1), meshed(1);
  auto take_normals = [&](LimbArena& arena) {
    if (packed_normals == nullptr) return;  // the worker failed to size them
    NormalScratch scratch(*this, packed_normals->packed_for_writing(), arena);
    std::size_t unreported = 0;
    normals.take([&](std::size_t begin, std::size_t end) {
      write_normals(planes, begin, end, scratch);
      unreported += end - begin;
      if (unreported >= progress_chunk) progress.advance(std::exchange(unreported, 0));
    });
  };
  auto take_vertices = [&](LimbArena& arena) {
    if (positions == nullptr) return;  // the calling thread failed before sizing them
    if (scaled) {
      vertices.take([&](std::size_t begin, std::size_t end) {
        write_scaled_vertices(pairs, begin, end, *scaled, positions->scaled_for_writing(), vertex_approx.data());
      });
      return;
    }
    Vec3 scratch;  // for the sums that do not fit machine words
    const PackedOutput out{&positions->packed_for_writing(), vertex_approx.data(), &arena};
    vertices.take([&](std::size_t begin, std::size_t end) {
      if (!write_packed_vertices(pairs, begin, end, out, scratch)) {
        not_dyadic = true;
        vertices.give_up();
      }
    });
  };
  Mesh mesh;
  {
    Worker worker;
    try {
      worker.start([&] {
        CountDownOnce sized_done(sized);
        try {
          packed_normals = size_packed_planes(planes, facets);
          sized_done();
          take_normals(worker_limbs);
          meshed.wait();
          take_vertices(worker_vertex_limbs);
        } catch (...) {
          normals.give_up();
          vertices.give_up();
          throw;
        }
      });
    } catch (const std::system_error&) {
      return build_on_one_thread(progress);  // no thread to be had now: one thread builds the same polyhedron
    }
    CountDownOnce meshed_done(meshed);
    try {
      pairs.reserve(euler_vertex_count(soup));
      number_corners(soup, false, [&](const VertexPair& p) {
        pairs.push_back(p);
        return static_cast<std::uint32_t>(pairs.size() - 1);
      });
      vertex_approx.resize(pairs.size());
      // The topology reads only the number of points: both threads pack
      // their values into the mesh's points once it stands. (The mesh is
      // this function's until it returns: nothing reads them before.)
      positions = scaled ? std::make_shared<PackedVectors>(ScaledPoints(pairs.size(), scaled->denominator,
                                                                        carving_from<ScaledPoints::Int128>(slab)))
                         : std::make_shared<PackedVectors>(
                               DyadicPoints(pairs.size(), carving_from<PackedDyadic>(slab)));
      mesh = output_mesh(std::move(soup), positions, slab);
      vertices.set_size(pairs.size());
      meshed_done();
      sized.wait();
      take_normals(limbs);
      take_vertices(vertex_limbs);
    } catch (...) {
      normals.give_up();
      vertices.give_up();
      throw;  // the worker joins before the exception leaves
    }
    worker.join();  // rethrows the worker's exception
  }
  packed_normals->packed_for_writing().keep_limbs(std::move(limbs));
  packed_normals->packed_for_writing().keep_limbs(std::move(worker_limbs));
  LimbArena point_limbs;
  if (not_dyadic) {  // inputs with other rationals than dyadic ones: Vec3s
    std::vector<Vec3> points(pairs.size());
    Vec3 scratch;
    write_vertices(pairs, 0, pairs.size(), {points.data(), vertex_approx.data(), &point_limbs}, scratch);
    mesh = mesh.with_positions(std::move(points));
  } else {
    positions->packed_for_writing().keep_limbs(std::move(vertex_limbs));
    positions->packed_for_writing().keep_limbs(std::move(worker_vertex_limbs));
  }
  return assemble(std::move(mesh), std::move(vertex_approx), std::move(planes), std::move(point_limbs));
}

}  // namespace cvms::detail
