// SPDX-License-Identifier: MIT
// Building the facets of A + B from features of A and B, and stitching them
// into one ConvexPolyhedron (paper Sections 4.3 and 5.2: translated, corner
// and edge facets). Shared by every algorithm that knows, for each facet of
// the sum, which features of A and B it comes from (CVMS, ESSDMS).
//
// Every vertex of A + B is a_i + b_j for exactly one pair (i, j) of input
// vertices, so facets are recorded as counterclockwise cycles of index pairs
// and glued by pair: no coordinates are compared, and each output coordinate
// is computed once.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "dyadic_points.hpp"
#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"
#include "progress_reporter.hpp"
#include "realloc_vector.hpp"
#include "scaled_points.hpp"
#include "two_word_scaled.hpp"
#include "word_scaled.hpp"

namespace cvms::detail {

/// Which operand a facet (or edge) belongs to.
enum class Operand { a, b };

/// The vertex a_i + b_j of the sum.
struct VertexPair {
  std::uint32_t a;
  std::uint32_t b;
};

class SumFacetBuilder {
 public:
  /// The builder keeps references to a and b: they must outlive it.
  SumFacetBuilder(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

  /// Facet f of `which` translated by vertex v of the other operand (the
  /// single contributing vertex of f).
  void add_facet_plus_vertex(Operand which, FaceId f, VertexId v);
  /// Facet f of `which` plus the segment [v0, v1] of the other operand, an
  /// edge parallel to f's plane (two contributing vertices).
  void add_facet_plus_edge(Operand which, FaceId f, VertexId v0, VertexId v1);
  /// fa + fb for a facet of A and a facet of B with the same outward normal.
  void add_facet_plus_facet(FaceId fa, FaceId fb);
  /// The parallelogram e_A + e_B of the edges of halfedges ha (of A) and hb
  /// (of B), non-parallel, whose outward normal is cross(d_A, d_B) times
  /// `orientation` (positive or negative), d = to(h) - from(h).
  void add_edge_plus_edge(HalfedgeId ha, HalfedgeId hb, Sign orientation);

  /// Adds facets [begin, end) of other after these, in other's order.
  /// \pre other was built for the same operands; begin <= end <= other.num_facets().
  void append(const SumFacetBuilder& other, std::size_t begin, std::size_t end);

  [[nodiscard]] std::size_t num_facets() const noexcept { return offsets_.size() - 1; }
  /// The pairs of facet i, counterclockwise seen from outside.
  [[nodiscard]] std::vector<VertexPair> facet(std::size_t i) const;

  /// Glues the facets by vertex pair and builds the result. \pre the facets
  /// are exactly the facets of A + B (each maximal, strictly convex,
  /// counterclockwise from outside, no two with the same normal).
  /// The normals are not recomputed from the output: each is the known
  /// normal of the facet of A or B it is parallel to, or, for e_A + e_B, the
  /// primitive direction of +-cross(d_A, d_B).
  /// The planes' offsets are made on first use (ConvexPolyhedron::plane_offset).
  /// The vertices and normals are packed (dyadic_points.hpp), made into
  /// Vec3s only if a caller asks; vertices that are not dyadic (operands
  /// with other rationals) are Vec3s from the start.
  /// threads > 1 computes the facet normals on a second thread while this
  /// one numbers the vertices and builds the mesh's topology; then both
  /// share what is left of the normals and the vertices' coordinates (same
  /// result).
  /// When `progress` is given, the build reports the stage "sum: output" to
  /// it, in facet normals done, and stops by its Error(cancelled).
  [[nodiscard]] ConvexPolyhedron build(unsigned threads = 1, ProgressReporter* progress = nullptr) const;
  /// The mesh build() makes, with its points, but no facet planes: what
  /// every representation of the output needs (the benchmarks' `limit mesh`).
  [[nodiscard]] Mesh build_mesh() const;

  /// The glued facets as a soup: one point per distinct vertex pair (its
  /// exact coordinates computed once), facets in the order added. build()
  /// is Mesh::from_soup of this plus the known facet planes.
  [[nodiscard]] PolygonSoup soup() const;

 private:
  // The normals of the facets, once size_packed_planes (facet_planes.hpp)
  // has sized them all: write_normals fills facets [begin, end). Threads may
  // write disjoint ranges. (The offsets are made on first use.)
  struct NormalScratch;
  void write_normals(FacetPlanes& planes, std::size_t begin, std::size_t end, NormalScratch& scratch) const;
  // Facet i's normal and its approximation into planes.
  void write_normal(FacetPlanes& planes, std::size_t i, NormalScratch& scratch) const;
  [[nodiscard]] ConvexPolyhedron build_on_one_thread(ProgressReporter& progress) const;
  [[nodiscard]] ConvexPolyhedron build_on_two_threads(ProgressReporter& progress) const;
  // Facet normals written between two progress reports: a few milliseconds.
  static constexpr std::size_t progress_chunk = 4096;
  // build()'s mesh with its points, and the points' approximations. Points
  // that are not dyadic keep their limbs in *limbs, or their own if null.
  struct MeshWithApprox {
    Mesh mesh;
    VertexApproximations approx;
  };
  [[nodiscard]] MeshWithApprox mesh_with_points(LimbArena* limbs) const;
  // soup(), and if approx is not null the approximations of its points; if
  // limbs is not null, the points keep their limbs there.
  [[nodiscard]] PolygonSoup soup(VertexApproximations* approx, LimbArena* limbs) const;
  // A soup with the facets' corner offsets set, no indices (number_corners
  // writes them) and no points.
  [[nodiscard]] PolygonSoup faces_without_points() const;
  // Numbers the distinct vertex pairs by first use in facet order, calling
  // new_vertex(pair) -> its number for each in that order, and writes the
  // numbers into soup.face_indices. With prefetch_operands, the operands'
  // vertices of the next pairs are fetched ahead (for a new_vertex that
  // reads them).
  // Before pair j of those visited in order, up to `end`, is read: fetches
  // ahead the operands' vertices of the pairs a few places on (pair_at(k)
  // gives pair k).
  template <typename PairAt>
  void prefetch_operand_vertices(std::size_t j, std::size_t end, PairAt&& pair_at) const;
  template <typename NewVertex>
  void number_corners(PolygonSoup& soup, bool prefetch_operands, NewVertex&& new_vertex) const;
  // Where output vertex j goes: points[j], and approx[j] and the numerators'
  // limbs if those are not null.
  struct VertexOutput {
    Vec3* points;
    ApproxVec3* approx;
    LimbArena* limbs;
  };
  // Output vertex j, the sum of the vertices of pair p, into out.
  void write_vertex(const VertexPair& p, const VertexOutput& out, std::size_t j, Vec3& scratch) const;
  // Where output vertex j goes when packed: points->coordinate(j, axis) and
  // approx[j], long numerators' limbs in limbs.
  struct PackedOutput {
    DyadicPoints* points;
    ApproxVec3* approx;
    LimbArena* limbs;
  };
  // write_vertex, packed; false (vertex j unspecified) when a coordinate is
  // not dyadic, which only inputs with other rationals make.
  bool write_packed_vertex(const VertexPair& p, const PackedOutput& out, std::size_t j, Vec3& scratch) const;
  // write_packed_vertex for the vertices [begin, end) of pairs; false as soon as one fails.
  bool write_packed_vertices(std::span<const VertexPair> pairs, std::size_t begin, std::size_t end,
                             const PackedOutput& out, Vec3& scratch) const;
  // Both operands' vertices as integers over their common denominators, in
  // one word (word_scaled.hpp: a and b) or else in two (two_word_scaled.hpp:
  // wide_a and wide_b, a and b null), and the output's denominator
  // L = lcm(D_A, D_B) with each operand's factor to it (scaled_points.hpp).
  // One-word operands keep one-word factors: a 64 x 64-bit product is one
  // multiplication, a 128 x 128-bit one three.
  struct ScaledSum {
    const WordScaledPoints* a;
    const WordScaledPoints* b;
    ScaledPoints::Uint128 denominator;
    std::uint64_t factor_a;  // L / D_A, with a and b
    std::uint64_t factor_b;  // L / D_B, with a and b
    const TwoWordScaledPoints* wide_a = nullptr;
    const TwoWordScaledPoints* wide_b = nullptr;
    ScaledPoints::Uint128 wide_factor_a = 0;  // L / D_A, with wide_a and wide_b
    ScaledPoints::Uint128 wide_factor_b = 0;  // L / D_B, with wide_a and wide_b
  };
  // The scaled operands when both have them (in one word, else in two with
  // sums that fit 128 bits) and some coordinate is not a double (operands
  // of doubles keep the dyadic path); nullopt otherwise.
  [[nodiscard]] std::optional<ScaledSum> scaled_sum() const;
  // The two-word form of scaled_sum(), when both operands have it, some
  // coordinate is not dyadic and their sums fit (two_word_sum_fits);
  // nullopt otherwise.
  [[nodiscard]] std::optional<ScaledSum> two_word_scaled_sum() const;
  // Output vertex j, the sum of the vertices of pair p, as integers over
  // sum.denominator into points, with its approximation into approx[j].
  void write_scaled_vertex(const VertexPair& p, const ScaledSum& sum, ScaledPoints& points, ApproxVec3* approx,
                           std::size_t j) const;
  // write_scaled_vertex for the vertices [begin, end) of pairs. Threads may
  // write disjoint ranges.
  void write_scaled_vertices(std::span<const VertexPair> pairs, std::size_t begin, std::size_t end,
                             const ScaledSum& sum, ScaledPoints& points, ApproxVec3* approx) const;
  // The output's mesh of faces with its points as ScaledPoints, and their
  // approximations; points and connectivity carved from slab.
  [[nodiscard]] Mesh scaled_mesh(PolygonSoup faces, VertexApproximations& approx,
                                 const std::shared_ptr<ResultSlab>& slab, const ScaledSum& sum) const;
  // The output's mesh of faces (faces_without_points()) with its points
  // packed, and their approximations; or nullopt when a vertex is not dyadic.
  // Points and connectivity are carved from slab.
  [[nodiscard]] std::optional<Mesh> packed_mesh(PolygonSoup faces, VertexApproximations& approx,
                                                const std::shared_ptr<ResultSlab>& slab) const;
  // One slab for the output's packed points, their approximations and its
  // mesh's connectivity (result_slab.hpp; the planes take one of their own:
  // size_packed_planes),
  // sized from the counts the search fixed: faces are faces_without_points().
  [[nodiscard]] std::shared_ptr<ResultSlab> output_slab(const PolygonSoup& faces) const;
  // write_vertex for the vertices [begin, end) of pairs. Threads may write
  // disjoint ranges.
  void write_vertices(std::span<const VertexPair> pairs, std::size_t begin, std::size_t end,
                      const VertexOutput& out, Vec3& scratch) const;
  void add_planar_sum(Operand which, FaceId f, std::span<const VertexId> other);
  // Where the normal of an output facet comes from: facet `index` of A or B,
  // or the edges of halfedges (index, other) with the given orientation.
  enum class NormalKind : std::uint8_t { facet_a, facet_b, edges_positive, edges_negative };
  struct NormalSource {
    NormalKind kind;
    std::uint32_t index;
    std::uint32_t other;
  };
  // An edge facet e_A + e_B keeps no pairs: its four corners follow from
  // its two halfedges and orientation (edge_cycle), which its normal source
  // holds already. The search may record millions of them before the output
  // budget refuses a hostile pair; this way each costs 16 bytes, not 48.
  static bool is_edge_facet(const NormalSource& source) noexcept {
    return source.kind == NormalKind::edges_positive || source.kind == NormalKind::edges_negative;
  }
  [[nodiscard]] std::array<VertexPair, 4> edge_cycle(const NormalSource& source) const;
  // The offsets of each facet's first corner in the sequence of all corners.
  [[nodiscard]] std::vector<std::uint32_t> corner_offsets() const;
  // visit(pair) for the corners of every facet, in order, without storing
  // them: the soup of an honest sum would page in a fresh copy otherwise.
  template <typename Visit>
  void for_each_corner(Visit&& visit) const {
    for (std::size_t i = 0; i < num_facets(); ++i) {
      if (is_edge_facet(normals_[i])) {
        for (const VertexPair& p : edge_cycle(normals_[i])) visit(p);
      } else {
        for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) visit(pairs_[k]);
      }
    }
  }
  void close_facet(NormalSource normal) {
    offsets_.push_back(static_cast<std::uint32_t>(pairs_.size()));
    normals_.push_back(normal);
  }
  static NormalSource facet_normal(Operand which, FaceId f) {
    return {which == Operand::a ? NormalKind::facet_a : NormalKind::facet_b, f.index(), 0};
  }
  void push(Operand which, VertexId own, VertexId other) {
    pairs_.push_back(which == Operand::a ? VertexPair{own.index(), other.index()}
                                         : VertexPair{other.index(), own.index()});
  }
  [[nodiscard]] const ConvexPolyhedron& operand(Operand which) const noexcept {
    return which == Operand::a ? a_ : b_;
  }

  const ConvexPolyhedron& a_;
  const ConvexPolyhedron& b_;
  // Grown by realloc: see realloc_vector.hpp for why.
  ReallocVector<std::uint32_t> offsets_{0};
  ReallocVector<VertexPair> pairs_;
  ReallocVector<NormalSource> normals_;
  // Scratch buffers, reused between facets.
  std::vector<VertexId> own_vertices_;
  std::vector<Vec2> own_points_;
  std::vector<Vec2> other_points_;
  std::vector<VertexId> other_vertices_;
};

}  // namespace cvms::detail
