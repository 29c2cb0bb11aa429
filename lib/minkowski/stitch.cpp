// SPDX-License-Identifier: MIT
// Facets of A + B from features of A and B, glued by vertex pair (paper
// Section 4.3; shared with the slope-diagram algorithm of Section 5.2).
#include "stitch.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "cvms/planar_sum.hpp"
#include "dyadic.hpp"
#include "error_bounds.hpp"
#include "first_use.hpp"
#include "polyhedron_builder.hpp"
#include "small_direction.hpp"
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

Vec2 project(const Vec3& p, Projection pr) { return {p[pr.u], p[pr.v]}; }

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
// endpoints are doubles, rationals otherwise.
class EdgeDirections {
 public:
  explicit EdgeDirections(const ConvexPolyhedron& p) : p_(p), state_(p.num_edges(), State::unknown) {}

  // The small direction of h's edge, or nullptr if it has none.
  const SmallDirection* small(HalfedgeId h) {
    const std::uint32_t e = Mesh::edge(h).index();
    if (state_[e] == State::unknown) {
      if (small_.empty()) small_.resize(state_.size());
      const Mesh& m = p_.mesh();
      const HalfedgeId even = Mesh::halfedge(Mesh::edge(h));
      const auto d = small_integer_direction(detail::vertex_approx(p_, m.from(even)), detail::vertex_approx(p_, m.to(even)));
      state_[e] = d ? State::small : State::general;
      if (d) small_[e] = *d;
    }
    return state_[e] == State::small ? &small_[e] : nullptr;
  }

  // The direction of h's edge as rationals (rarely needed: only when the
  // other edge of an edge facet has no small direction).
  const Vec3& general(HalfedgeId h) {
    const std::uint32_t e = Mesh::edge(h).index();
    auto [it, inserted] = general_.try_emplace(e);
    if (inserted) {
      const SmallDirection* s = small(h);
      it->second =
          s != nullptr ? s->to_vec3() : primitive_direction(p_.edge_vector(Mesh::halfedge(Mesh::edge(h))));
    }
    return it->second;
  }

 private:
  enum class State : std::uint8_t { unknown, small, general };
  const ConvexPolyhedron& p_;
  std::vector<State> state_;
  std::vector<SmallDirection> small_;
  std::unordered_map<std::uint32_t, Vec3> general_;
};

// Approx::of(x + y) from the approximations of x and y when both are exact
// doubles, without converting the exact sum back from GMP: TwoSum (Knuth)
// gives the nearest double s and the exact rounding error r = x + y - s;
// Approx::of truncates toward zero, which is s itself when r is zero or
// points away from zero, and the next double toward zero otherwise. The
// error bound is Approx::of's, so the cached value is the same either way
// (error_bounds.hpp says why this sum is not bounded as CHMS's sums are).
Approx approx_sum(const Approx& x, const Approx& y, const Rational& exact_sum) noexcept {
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
  return Approx::of(exact_sum);
}

// A dense pair -> output-index table is used when it is not much larger than
// the output itself; otherwise a hash map.
constexpr std::uint64_t dense_table_limit = 1u << 16;

// The threaded build's work in the order it is handed out by one atomic
// counter: sizing the planes (one task), the vertex sums, then the planes, in
// chunks, so the split adapts to the input (any split gives the same exact
// values). A thread only waits for the sizing, and only once some running
// thread has taken it, so a worker that failed to start blocks nobody.
class BuildQueue {
 public:
  enum class Kind { size_planes, vertices, planes, done };
  struct Task {
    Kind kind;
    std::size_t begin;
    std::size_t end;
  };

  BuildQueue(std::size_t vertices, std::size_t facets)
      : vertices_(vertices),
        facets_(facets),
        vertex_chunks_(chunks(vertices)),
        tasks_(1 + vertex_chunks_ + chunks(facets)) {}

  // One thread per task at most, the caller (building the mesh) aside.
  [[nodiscard]] unsigned tasks() const noexcept {
    return static_cast<unsigned>(std::min<std::size_t>(tasks_, std::numeric_limits<unsigned>::max()));
  }

  Task next() {
    const std::size_t t = next_.fetch_add(1, std::memory_order_relaxed);
    if (t == 0) return {Kind::size_planes, 0, 0};
    if (t <= vertex_chunks_) return chunk(Kind::vertices, t - 1, vertices_);
    if (t < tasks_) return chunk(Kind::planes, t - 1 - vertex_chunks_, facets_);
    return {Kind::done, 0, 0};
  }

  // Runs the sizing and tells the waiting threads whether it succeeded.
  template <class F>
  void size_planes(F size) {
    try {
      size();
    } catch (...) {
      publish(State::failed);
      throw;
    }
    publish(State::sized);
  }

  // False if the sizing failed.
  bool wait_for_planes() {
    state_.wait(State::pending);
    return state_.load() == State::sized;
  }

 private:
  static constexpr std::size_t chunk_size = 256;
  enum class State { pending, sized, failed };
  static std::size_t chunks(std::size_t n) { return (n + chunk_size - 1) / chunk_size; }
  static Task chunk(Kind kind, std::size_t index, std::size_t n) {
    const std::size_t begin = index * chunk_size;
    return {kind, begin, std::min(begin + chunk_size, n)};
  }
  void publish(State s) {
    state_.store(s);
    state_.notify_all();
  }

  std::size_t vertices_;
  std::size_t facets_;
  std::size_t vertex_chunks_;
  std::size_t tasks_;
  std::atomic<std::size_t> next_{0};
  std::atomic<State> state_{State::pending};
};

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
  own_points_.clear();
  for (HalfedgeId h : own.mesh().face_halfedges(f)) {
    const VertexId v = own.mesh().from(h);
    own_vertices_.push_back(v);
    own_points_.push_back(project(own.vertex(v), pr));
  }
  other_points_.clear();
  for (VertexId v : other) other_points_.push_back(project(oth.vertex(v), pr));
  for (const auto& [i, j] : planar_sum_indices(own_points_, other_points_)) {
    push(which, own_vertices_[i], other[j]);
  }
  close_facet(facet_normal(which, f));
}

void SumFacetBuilder::add_edge_plus_edge(HalfedgeId ha, HalfedgeId hb, Sign orientation) {
  const Mesh& ma = a_.mesh();
  const Mesh& mb = b_.mesh();
  const std::uint32_t ua = ma.from(ha).index();
  const std::uint32_t va = ma.to(ha).index();
  const std::uint32_t ub = mb.from(hb).index();
  const std::uint32_t vb = mb.to(hb).index();
  // The cycle ua+ub, va+ub, va+vb, ua+vb has edge vectors d_A, d_B, -d_A,
  // -d_B, hence normal cross(d_A, d_B); reversed, the opposite normal.
  const VertexPair cycle[4] = {{ua, ub}, {va, ub}, {va, vb}, {ua, vb}};
  if (orientation == Sign::positive) {
    for (int i = 0; i < 4; ++i) pairs_.push_back(cycle[i]);
  } else {
    for (int i = 3; i >= 0; --i) pairs_.push_back(cycle[i]);
  }
  close_facet({orientation == Sign::positive ? NormalKind::edges_positive : NormalKind::edges_negative,
               ha.index(), hb.index()});
}

void SumFacetBuilder::append(const SumFacetBuilder& other, std::size_t begin, std::size_t end) {
  const std::uint32_t first = other.offsets_[begin];
  const std::uint32_t base = static_cast<std::uint32_t>(pairs_.size()) - first;
  pairs_.insert(pairs_.end(), other.pairs_.begin() + first, other.pairs_.begin() + other.offsets_[end]);
  for (std::size_t i = begin + 1; i <= end; ++i) offsets_.push_back(base + other.offsets_[i]);
  normals_.insert(normals_.end(), other.normals_.begin() + static_cast<std::ptrdiff_t>(begin),
                  other.normals_.begin() + static_cast<std::ptrdiff_t>(end));
}

PolygonSoup SumFacetBuilder::soup() const { return soup(nullptr); }

PolygonSoup SumFacetBuilder::soup(std::vector<ApproxVec3>* approx) const {
  Numbering numbered = number_vertices();
  const std::size_t n = numbered.vertices.size();
  // Sized first, then written in place: moving an mpq_class re-initialises
  // the source, which allocates.
  numbered.soup.points.resize(n);
  if (approx != nullptr) approx->resize(n);
  sum_vertices(numbered.vertices, 0, n, numbered.soup.points,
               approx != nullptr ? std::span<ApproxVec3>(*approx) : std::span<ApproxVec3>());
  return std::move(numbered.soup);
}

SumFacetBuilder::Numbering SumFacetBuilder::number_vertices() const {
  const std::uint64_t nb = b_.num_vertices();
  const std::uint64_t table_size = std::uint64_t{a_.num_vertices()} * nb;
  Numbering out;
  out.soup.face_offsets = offsets_;
  out.soup.face_indices.resize(pairs_.size());
  if (table_size <= dense_table_limit || table_size <= 8 * std::uint64_t{pairs_.size()}) {
    constexpr std::uint32_t unset = ~std::uint32_t{0};
    std::vector<std::uint32_t> index(table_size, unset);
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
      std::uint32_t& slot = index[pairs_[i].a * nb + pairs_[i].b];
      if (slot == unset) {
        slot = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(pairs_[i]);
      }
      out.soup.face_indices[i] = slot;
    }
  } else {
    // Sparse: numbered by sorting, not hashing (std::hash of an integer is
    // the identity, so keys j * nb + v that an input lines up modulo the
    // bucket count would make a hash map quadratic; issue 18, item 1).
    std::vector<std::uint64_t> keys(pairs_.size());
    for (std::size_t i = 0; i < pairs_.size(); ++i) keys[i] = pairs_[i].a * nb + pairs_[i].b;
    detail::FirstUse numbered = detail::first_use(keys, std::less<>{});
    out.vertices.reserve(numbered.first.size());
    for (const std::size_t first : numbered.first) out.vertices.push_back(pairs_[first]);
    out.soup.face_indices = std::move(numbered.index);
  }
  return out;
}

void SumFacetBuilder::sum_vertices(std::span<const VertexPair> vertices, std::size_t begin, std::size_t end,
                                   std::span<Vec3> points, std::span<ApproxVec3> approx) const {
  for (std::size_t i = begin; i < end; ++i) {
    const VertexId va(vertices[i].a), vb(vertices[i].b);
    Vec3& sum = points[i];
    for (int k = 0; k < 3; ++k) add_into(sum[k], a_.vertex(va)[k], b_.vertex(vb)[k]);
    if (approx.empty()) continue;
    const ApproxVec3 &xa = detail::vertex_approx(a_, va), &xb = detail::vertex_approx(b_, vb);
    approx[i] = {approx_sum(xa.x, xb.x, sum.x), approx_sum(xa.y, xb.y, sum.y), approx_sum(xa.z, xb.z, sum.z)};
  }
}

// What one thread needs to write planes: reused scratch and its own lazy
// caches of edge directions.
struct SumFacetBuilder::PlaneScratch {
  explicit PlaneScratch(const SumFacetBuilder& builder)
      : directions_a(builder.a_), directions_b(builder.b_) {}
  EdgeDirections directions_a;
  EdgeDirections directions_b;
  Vec3 first_vertex_sum;
  DotScratch dot;
};

FacetPlanes SumFacetBuilder::sized_planes() const {
  // Default-constructed rationals (each allocates its denominator) that
  // write_planes overwrites in place: moving a rational into place would
  // re-initialise the source, which allocates again.
  const std::size_t n = num_facets();
  FacetPlanes planes;
  planes.normals.resize(n);
  planes.normal_approx.resize(n);
  planes.offsets.resize(n);
  return planes;
}

void SumFacetBuilder::write_planes(FacetPlanes& planes, std::size_t begin, std::size_t end, const Mesh* mesh,
                                   PlaneScratch& scratch) const {
  for (std::size_t i = begin; i < end; ++i) {
    const NormalSource& source = normals_[i];
    Vec3& normal = planes.normals[i];
    switch (source.kind) {
      case NormalKind::facet_a:
        normal = a_.normal(FaceId(source.index));
        break;
      case NormalKind::facet_b:
        normal = b_.normal(FaceId(source.index));
        break;
      case NormalKind::edges_positive:
      case NormalKind::edges_negative: {
        // The directions belong to the even halfedge of each edge.
        const HalfedgeId ha(source.index), hb(source.other);
        const SmallDirection* da = scratch.directions_a.small(ha);
        const SmallDirection* db = scratch.directions_b.small(hb);
        if (da != nullptr && db != nullptr)
          primitive_cross(*da, *db, normal);
        else
          primitive_cross(scratch.directions_a.general(ha), scratch.directions_b.general(hb), normal);
        const bool flip =
            (source.kind == NormalKind::edges_negative) != ((ha.index() & 1u) != (hb.index() & 1u));
        if (flip)
          for (int k = 0; k < 3; ++k) mpq_neg(normal[k].get_mpq_t(), normal[k].get_mpq_t());
        break;
      }
    }
    planes.normal_approx[i] = ApproxVec3::of(normal);
    // The offset is taken at the facet's first vertex a_i + b_j: read from
    // the output mesh once it exists, else summed here (6 % more
    // instructions, but it lets this run while another thread builds the mesh).
    const Vec3* first_vertex = &scratch.first_vertex_sum;
    if (mesh != nullptr) {
      const FaceId f(static_cast<std::uint32_t>(i));
      first_vertex = &mesh->position(mesh->from(mesh->halfedge(f)));
    } else {
      const VertexPair& first = pairs_[offsets_[i]];
      const Vec3 &va = a_.vertex(VertexId(first.a)), &vb = b_.vertex(VertexId(first.b));
      for (int k = 0; k < 3; ++k) add_into(scratch.first_vertex_sum[k], va[k], vb[k]);
    }
    integer_dot(normal, *first_vertex, scratch.dot, planes.offsets[i]);
  }
}

ConvexPolyhedron SumFacetBuilder::build(unsigned threads) const {
  if (threads > 1) return build_threaded(threads);
  std::vector<ApproxVec3> vertex_approx;
  Mesh mesh = output_mesh(soup(&vertex_approx));
  FacetPlanes planes = sized_planes();
  PlaneScratch scratch(*this);
  write_planes(planes, 0, num_facets(), &mesh, scratch);
  return assemble(std::move(mesh), std::move(vertex_approx), std::move(planes));
}

// The threaded build: after the numbering (this thread), the caller builds
// the mesh's connectivity while the others size the planes and then all
// share the vertex sums and the planes in chunks (BuildQueue). The mesh
// takes the points before their sums are written: output_mesh only moves
// them, and moving a vector keeps its elements where they are.
ConvexPolyhedron SumFacetBuilder::build_threaded(unsigned threads) const {
  Numbering numbered = number_vertices();
  const std::size_t num_vertices = numbered.vertices.size();
  numbered.soup.points.resize(num_vertices);  // in place, as in soup()
  std::vector<ApproxVec3> vertex_approx(num_vertices);
  const std::span<Vec3> points(numbered.soup.points);
  Mesh mesh;
  FacetPlanes planes;
  BuildQueue queue(num_vertices, num_facets());
  run_on_threads(std::min(threads, queue.tasks()), [&](unsigned thread) {
    if (thread == 0) mesh = output_mesh(std::move(numbered.soup));
    PlaneScratch scratch(*this);
    for (BuildQueue::Task task = queue.next(); task.kind != BuildQueue::Kind::done; task = queue.next()) {
      switch (task.kind) {
        case BuildQueue::Kind::size_planes:
          queue.size_planes([&] { planes = sized_planes(); });
          break;
        case BuildQueue::Kind::vertices:
          sum_vertices(numbered.vertices, task.begin, task.end, points, vertex_approx);
          break;
        case BuildQueue::Kind::planes:
          if (!queue.wait_for_planes()) return;  // sizing them failed: its thread reports it
          write_planes(planes, task.begin, task.end, nullptr, scratch);
          break;
        case BuildQueue::Kind::done:
          break;
      }
    }
  });
  return assemble(std::move(mesh), std::move(vertex_approx), std::move(planes));
}

}  // namespace cvms::detail
