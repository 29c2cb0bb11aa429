// SPDX-License-Identifier: MIT
// Exact 3D quickhull (Barber, Dobkin and Huhdanpaa 1996, the paper's [10]),
// the hull behind CHMS (paper Section 6.2). Every decision is the exact sign
// of a predicate on the exact input points, so the result is the exact hull
// whatever the input.
//
// Speed comes from deciding in double whenever a proven bound allows it:
// each triangle gets a semi-static plane filter (plane_filter.hpp) against
// which conflict and visibility tests cost a dot product; the initial
// simplex scans the points' doubles with a bound of its own; the remaining
// tests use the predicates' running-error filters (filter_polynomials.hpp)
// on the points' doubles. Only undecided tests reach the exact predicates.
// Every bound, with its proof, is in error_bounds.hpp. The points may come
// as rationals, as doubles, or as approximations with exact values made on
// demand (ApproximatePoints), so that double input and CHMS's pairwise sums
// need no rational for most points. The decisions, hence the output, do not
// depend on which.
//
// Construction keeps a triangulated hull whose triangles are oriented
// counterclockwise from outside. A point is "outside" a triangle only when it
// is STRICTLY above its plane; coplanar points are treated as not outside and
// are dropped as soon as no triangle sees them. Such points never create
// split facets later: a point on the hull's boundary that no triangle sees is
// a convex combination of hull vertices, so it cannot be extreme. Coplanar
// triangles do arise (a point coplanar with a horizon neighbour, or a vertex
// that later ends up inside a facet or on an edge), so at the end adjacent
// coplanar triangles are merged into one polygon per plane, and polygon
// corners that are collinear with their neighbours are dropped: what remains
// are exactly the extreme points, which are corners of every facet they lie on.
//
// Why strict visibility is enough (exact arithmetic makes these hold):
// - the triangles strictly visible from a point outside form a disk, so the
//   horizon is one simple cycle and each horizon vertex starts exactly one
//   horizon edge (that is how the new cone is linked, without ordering);
// - a new triangle (horizon edge, eye) is never flat: the eye is strictly
//   above the visible triangle that contains the edge;
// - if a point q in the conflict list of a deleted triangle is outside the new
//   hull, it is strictly above one of the new triangles (the new triangle's
//   normal at a horizon edge is a non-negative combination of the normals of
//   the two old triangles there), so testing q against the new triangles only
//   is enough.
//
// Plane triples. Every triangle carries three points spanning its plane,
// counterclockwise from outside (Triangle::plane), and the exact fallbacks
// ask about the triple instead of the corners, so that every triangle of
// one plane asks the same question and a caller's cache per triple serves
// them all. Invariant: a live triangle's triple spans the triangle's plane
// and has the same orientation as its corners. A new triangle takes its own
// corners, except a cone triangle T = (a, b, eye) built against a hidden
// neighbour h = (b, a, c) whose plane P holds the eye: it takes h's triple.
// Proof that this keeps the invariant: a, b and the eye lie in P and T is
// not flat, so T's plane is P. The visible triangle t across the horizon
// edge has a and b on its plane, the eye strictly above it and c strictly
// below it (c is below or on it by convexity, and on it would put h, and
// with it the eye, in t's plane). P meets t's plane in the line ab, so in P
// the eye and c lie on opposite sides of that line; T and h run the edge
// in opposite directions, so they have the same orientation in P, that is,
// the same outward normal, which h's triple has too.
#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "approx.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/error.hpp"
#include "dyadic_orient.hpp"
#include "error_bounds.hpp"
#include "filter_polynomials.hpp"
#include "filtered_predicates.hpp"
#include "huge_page_blocks.hpp"
#include "hull_soup.hpp"
#include "index_hash.hpp"
#include "no_index.hpp"
#include "plane_filter.hpp"
#include "polyhedron_builder.hpp"

namespace cvms {
namespace {

constexpr std::uint32_t none = detail::no_index;

using FacePlane = std::array<std::uint32_t, 3>;
using detail::cache_bits;
using detail::index_slot;
using detail::ScratchVector;

constexpr std::uint32_t next3(std::uint32_t i) { return i == 2 ? 0 : i + 1; }
constexpr std::uint32_t prev3(std::uint32_t i) { return i == 0 ? 2 : i - 1; }

struct Triangle {
  std::uint32_t v[3];   // point indices, counterclockwise seen from outside
  // Three points spanning the triangle's plane, counterclockwise seen from
  // outside: its own corners, or those of the coplanar triangle it was built
  // against (see expand). Equal triples mean one plane, proven when the
  // triangle was made; the exact fallbacks ask about this triple, so that
  // every triangle of a plane shares the caller's cached work for it.
  std::uint32_t plane[3];
  std::uint32_t nb[3];  // nb[i]: the triangle across edge v[i] -> v[i+1]
  std::uint32_t begin;  // conflict list: pool_[begin, end)
  std::uint32_t end;
  std::uint32_t farthest;  // the farthest conflict is pool_[begin + farthest]
  std::uint32_t stamp;     // iteration in which `visible` was decided
  bool visible;
  bool eye_in_plane;  // decided with `visible`: the eye lies in this plane
  bool alive;
  bool has_normal;  // normals_[t] is the exact normal of this triangle
};

// An outside point in a conflict list, with a copy of its double
// approximation: conflict lists are scanned over and over, and reading them
// sequentially instead of gathering from the per-point array is much kinder
// to the cache (20-35% faster on 10^6 random points).
struct Conflict {
  Coords c;
  std::uint32_t point;
};

// An exact orient3d answer, remembered (Quickhull::exact_answer).
struct ExactAnswer {
  std::uint32_t a = 0, b = 0, c = 0, d = 0;
  std::int8_t sign = 0;  // a Sign; one byte keeps the slot at 20 bytes
  bool known = false;
};

struct HorizonEdge {
  std::uint32_t a, b;       // the edge as it runs in the visible triangle
  std::uint32_t neighbour;  // the hidden triangle across it
};

class Quickhull {
 public:
  // Exact input: the filters run on the points' doubles and the largest error
  // bound of their approximations, which covers every point.
  explicit Quickhull(std::span<const Vec3> points) : points_(points), exact_input_(true) {
    n_ = checked_size(points.size());
    own_coords_.reserve(n_);
    PlaneFilterExtent extent;
    for (const Vec3& p : points) {
      const ApproxVec3 a = ApproxVec3::of(p);
      own_coords_.push_back(coords_of(a));
      extent.add(a);
    }
    coords_ = own_coords_;
    error_ = extent.max_error;
    scale_ = extent.scale();
    lazy_.assign(n_, none);
  }

  // Approximations only (double input is exact, with error 0): only the
  // points that an exact fallback or the output needs become rationals.
  explicit Quickhull(const ApproximatePoints& points, ExactOrient orient = {}, ExactCompareOrient compare = {})
      : coords_(points.approx),
        make_exact_(points.exact),
        exact_orient_(std::move(orient)),
        exact_compare_(std::move(compare)),
        copy_points_(!exact_orient_) {
    n_ = checked_size(coords_.size());
    PlaneFilterExtent extent;
    for (const Coords& c : coords_) extent.add(c);
    extent.add_error(points.max_error);
    error_ = extent.max_error;
    scale_ = extent.scale();
    lazy_.assign(n_, none);
  }

  // The stage "hull" (cvms/progress.hpp), in input points settled: on or
  // inside the hull so far, or outside the conflict lists. \pre before run().
  void report_to(detail::ProgressReporter* progress) noexcept {
    progress_ = progress != nullptr ? progress : &silent_;
  }

  PolygonSoup run(std::vector<std::uint32_t>* source_index, std::vector<FacePlane>* face_planes = nullptr) {
    progress_->begin("hull", n_);
    std::uint32_t simplex[4];
    initial_simplex(simplex);
    reserve_for_points();
    build_simplex(simplex);
    expand();
    PolygonSoup soup = extract(source_index, face_planes);
    progress_->end();
    predicate_counters().filtered += plane_decisions_;
    return soup;
  }

 private:
  static constexpr double inf = std::numeric_limits<double>::infinity();

  static std::uint32_t checked_size(std::size_t n) {
    if (n >= none)
      throw Error(ErrorCategory::limit,
                  "convex hull: " + std::to_string(n) + " points exceed the limit of 2^32 - 2");
    return static_cast<std::uint32_t>(n);
  }

  // The exact point p with its own approximation, made on first use (deques:
  // references stay valid): only the exact fallbacks and the output ask, for
  // few points, and a per-point approximation made for all of them up front
  // was 48 of the 72 bytes a point that every call touched (page faults
  // under glibc's default policy, which returns freed memory).
  [[nodiscard]] Vec3Ref ref(std::uint32_t p) {
    if (lazy_[p] == none) {
      lazy_[p] = static_cast<std::uint32_t>(lazy_approx_.size());
      const Vec3& point = exact_input_ ? points_[p] : lazy_points_.emplace_back(make_exact_(p));
      lazy_approx_.push_back(ApproxVec3::of(point));
    }
    return {exact_input_ ? points_[p] : lazy_points_[lazy_[p]], lazy_approx_[lazy_[p]]};
  }
  [[nodiscard]] const Vec3& exact(std::uint32_t p) { return exact_input_ ? points_[p] : ref(p).exact; }

  // The approximation of p as the filters see it: its doubles with the error
  // error_ that bounds every point's, or the doubles alone when that is 0.
  [[nodiscard]] ApproxVec3 approx(std::uint32_t p) const {
    const Coords& c = coords_[p];
    return {{c[0], error_}, {c[1], error_}, {c[2], error_}};
  }
  [[nodiscard]] filtered::Doubles3 doubles(std::uint32_t p) const {
    const Coords& c = coords_[p];
    return {c[0], c[1], c[2]};
  }

  // orient3d(a, b, c, d) and compare_dot(v, w, n) of points, first with the
  // predicates' running-error filter on the double coordinates (so that
  // double input needs no rationals when it answers), else by the exact
  // predicate. The filter decisions are counted here and added to the
  // thread's counters once, at the end.
  [[nodiscard]] Sign orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    const Approx r = error_ == 0.0 ? filtered::orient3d_approx(doubles(a), doubles(b), doubles(c), doubles(d))
                                   : filtered::orient3d_approx(approx(a), approx(b), approx(c), approx(d));
    if (filtered::certain(r)) {
      ++plane_decisions_;
      return filtered::sign(r);
    }
    return exact_orient(a, b, c, d);
  }

  // orient3d decided exactly: by the caller's predicate when it gave one, in
  // integers when the coordinates are dyadic (doubles, sums of doubles), else
  // by the predicates module.
  [[nodiscard]] Sign exact_orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    ExactAnswer& memo = exact_answer(a, b, c, d);
    if (memo.known && memo.a == a && memo.b == b && memo.c == c && memo.d == d) return static_cast<Sign>(memo.sign);
    const Sign sign = evaluate_orient(a, b, c, d);
    memo = {a, b, c, d, static_cast<std::int8_t>(sign), true};
    return sign;
  }

  // The slot of the exact answers for (a, b, c, d), direct-mapped, made on
  // the first exact question. With the triangles of one plane sharing its
  // triple, the same question comes again: on the coplanar dual points of
  // Sphere5's facet planes a third of the exact questions were repeats
  // (the plane of several hidden neighbours against the eye, a point
  // against several cone triangles of one plane), nearly all exact zeros.
  ExactAnswer& exact_answer(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (answers_.empty()) {
      // At least half as many slots as points, between 2^8 and 2^12 (20
      // bytes each).
      answer_bits_ = cache_bits(n_, 8, 12);
      answers_.resize(std::size_t{1} << answer_bits_);
    }
    return answers_[index_slot(answer_bits_, a, b, c, d)];
  }

  [[nodiscard]] Sign evaluate_orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (exact_orient_) return exact_orient_(a, b, c, d);
    if (const std::optional<Sign> s = dyadic_orient3d(exact(a), exact(b), exact(c), exact(d))) {
      ++predicate_counters().exact;
      return *s;
    }
    return orient3d(ref(a), ref(b), ref(c), ref(d));
  }

  // Sign of point p with respect to triangle t: positive iff p is strictly
  // above (outside).
  [[nodiscard]] Sign side(std::uint32_t t, std::uint32_t p) {
    const PlaneFilter& plane = planes_[t];
    const double s = plane.value(coords_[p]);
    if (plane.above(s) || plane.below(s)) {
      ++plane_decisions_;
      return s > 0 ? Sign::positive : Sign::negative;
    }
    return plane_orient(t, p);
  }

  // orient3d of the plane points of t and p (the sign of orient3d of t's
  // corners and p: the same oriented plane).
  [[nodiscard]] Sign plane_orient(std::uint32_t t, std::uint32_t p) {
    const Triangle& tr = tris_[t];
    return orient(tr.plane[0], tr.plane[1], tr.plane[2], p);
  }

  [[nodiscard]] bool same_plane(std::uint32_t t, std::uint32_t u) const {
    const Triangle &a = tris_[t], &b = tris_[u];
    return a.plane[0] == b.plane[0] && a.plane[1] == b.plane[1] && a.plane[2] == b.plane[2];
  }

  // ---- initial simplex ------------------------------------------------------

  [[noreturn]] void degenerate(const std::string& what) const {
    std::string msg = "convex hull: " + what + ", the points do not span 3D";
    if (n_ < 4) msg += " (" + std::to_string(n_) + " points; at least 4 are needed)";
    throw Error(ErrorCategory::degenerate, msg);
  }

  // Index of a point with the largest (sign > 0) or smallest (sign < 0) dot
  // product with direction d; the first such point on ties.
  [[nodiscard]] std::uint32_t extreme(Vec3Ref d, Sign sign) {
    const double bound = dot_bound(d.approx);
    if (!(bound < inf)) {
      std::uint32_t best = 0;
      for (std::uint32_t i = 1; i < n_; ++i)
        if (compare(i, best, d) == sign) best = i;
      return best;
    }
    // v = fl(p . n) is within bound of the exact dot product, so a point
    // whose v is more than 3 bounds (2 plus rounding, see difference_margin)
    // below the largest v is not extreme; the exact scan over the others, in
    // index order, picks the same (first extreme) point as a scan over all.
    const double f = sign == Sign::positive ? 1.0 : -1.0;
    const Coords n{f * d.approx.x.value, f * d.approx.y.value, f * d.approx.z.value};
    auto value = [&](std::uint32_t i) {
      const Coords& c = coords_[i];
      return c[0] * n[0] + c[1] * n[1] + c[2] * n[2];
    };
    double top = -inf;
    for (std::uint32_t i = 0; i < n_; ++i) top = std::max(top, value(i));
    const double margin = filtered::difference_margin * bound;
    std::uint32_t best = none;
    for (std::uint32_t i = 0; i < n_; ++i) {
      if (top - value(i) > margin) {
        ++plane_decisions_;
        continue;
      }
      if (best == none || compare(i, best, d) == sign) best = i;
    }
    return best;
  }

  // A bound on |P . N - fl(p . n)| for every input point P with
  // approximation p and the direction N with approximation n, or infinity
  // (error_bounds.hpp, "The dot-product scan").
  [[nodiscard]] double dot_bound(const ApproxVec3& n) const {
    return filtered::dot_filter_bound(n, 0.5 * scale_.span, error_);
  }

  // compare_dot(p, q, d), first filtered on the double coordinates.
  [[nodiscard]] Sign compare(std::uint32_t p, std::uint32_t q, Vec3Ref d) {
    const ApproxVec3& n = d.approx;
    const Approx r = error_ == 0.0 && filtered::all_exact(n)
                         ? filtered::compare_dot_approx(doubles(p), doubles(q), filtered::values(n))
                         : filtered::compare_dot_approx(approx(p), approx(q), n);
    if (filtered::certain(r)) {
      ++plane_decisions_;
      return filtered::sign(r);
    }
    return compare_dot(ref(p), ref(q), d);
  }

  // Picks four affinely independent points far apart, or reports the
  // dimension of the input. Only comparisons of dot products are used.
  void initial_simplex(std::uint32_t s[4]) {
    if (n_ == 0) degenerate("there are no points");
    // Extremes along the first axis on which the points differ.
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    std::uint32_t lo = 0, hi = 0;
    for (int k = 0; k < 3 && lo == hi; ++k) {
      const ApproxVec3 axis_approx = ApproxVec3::of(axes[k]);
      const Vec3Ref axis{axes[k], axis_approx};
      lo = extreme(axis, Sign::negative);
      hi = extreme(axis, Sign::positive);
      if (compare(lo, hi, axis) == Sign::zero) lo = hi;
    }
    if (lo == hi) degenerate("all " + std::to_string(n_) + " points are equal");
    s[0] = lo;
    s[1] = hi;

    // Third point: extreme along one of two directions orthogonal to the
    // line; a point is off the line iff its dot product with one of them
    // differs from the line's.
    const Vec3 d = exact(hi) - exact(lo);
    const Vec3 n1 = (sgn(d.y) != 0 || sgn(d.z) != 0) ? Vec3{0, d.z, -d.y} : Vec3{-d.z, 0, d.x};
    s[2] = off_extreme(n1, lo);
    if (s[2] == none) s[2] = off_extreme(cross(d, n1), lo);
    if (s[2] == none) degenerate("all " + std::to_string(n_) + " points are collinear");

    // Fourth point: extreme along the plane normal.
    s[3] = off_extreme(cross(exact(s[1]) - exact(s[0]), exact(s[2]) - exact(s[0])), lo);
    if (s[3] == none) degenerate("all " + std::to_string(n_) + " points are coplanar");
  }

  // Of the points with the largest and the smallest dot product with n, the
  // one farther from the plane through `base` orthogonal to n (a thin
  // initial simplex costs up to half again as many predicate calls on random
  // balls); none if all points lie in that plane.
  [[nodiscard]] std::uint32_t off_extreme(const Vec3& n, std::uint32_t base) {
    const ApproxVec3 na = ApproxVec3::of(n);
    const Vec3Ref nr{n, na};
    const std::uint32_t top = extreme(nr, Sign::positive), bottom = extreme(nr, Sign::negative);
    const bool top_off = compare(top, base, nr) != Sign::zero;
    const bool bottom_off = compare(bottom, base, nr) != Sign::zero;
    if (!top_off) return bottom_off ? bottom : none;
    if (!bottom_off) return top;
    // <top - base, n> >= <base - bottom, n>  iff  <top + bottom, n> >= <2 base, n>.
    const Vec3 sum = exact(top) + exact(bottom), twice = exact(base) + exact(base);
    const ApproxVec3 sa = ApproxVec3::of(sum), ta = ApproxVec3::of(twice);
    return compare_dot({sum, sa}, {twice, ta}, nr) != Sign::negative ? top : bottom;
  }

  // ---- triangles and conflict lists -----------------------------------------

  std::uint32_t new_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t t;
    if (!free_.empty()) {
      t = free_.back();
      free_.pop_back();
    } else {
      t = static_cast<std::uint32_t>(tris_.size());
      if (exact_orient_ && t == tris_.capacity()) reserve_dual_triangles(t);
      tris_.emplace_back();
      planes_.emplace_back();
      normal_slot_.push_back(none);
    }
    tris_[t] = Triangle{{a, b, c}, {a, b, c}, {none, none, none}, 0, 0, 0, 0, false, false, true, false};
    planes_[t] = PlaneFilter::of(coords_[a], coords_[b], coords_[c], scale_);
    return t;
  }

  // Only for visible triangles, whose conflicts distribute() has moved.
  void kill(std::uint32_t t) {
    tris_[t].begin = tris_[t].end = 0;
    tris_[t].alive = false;
    free_.push_back(t);
  }

  [[nodiscard]] Vec3Ref normal_ref(std::uint32_t t) {
    Triangle& tr = tris_[t];
    if (!tr.has_normal) {
      // Only triangles with two or more outside points need their normal.
      const Vec3& a = exact(tr.v[0]);
      if (normal_slot_[t] == none) {
        normal_slot_[t] = static_cast<std::uint32_t>(normals_.size());
        normals_.emplace_back();
        normal_approx_.emplace_back();
      }
      normals_[normal_slot_[t]] = cross(exact(tr.v[1]) - a, exact(tr.v[2]) - a);
      normal_approx_[normal_slot_[t]] = ApproxVec3::of(normals_[normal_slot_[t]]);
      tr.has_normal = true;
    }
    return {normals_[normal_slot_[t]], normal_approx_[normal_slot_[t]]};
  }

  // compare_dot(p, q, normal of t) == positive, where s_p and s_q are the
  // plane filter's values of p and q: each is within bound of the exact
  // orient3d, whose difference is that dot product, so a difference of the
  // values beyond 3 bounds (2 plus rounding, see difference_margin) decides.
  [[nodiscard]] bool farther(std::uint32_t t, double s_p, std::uint32_t p, double s_q, std::uint32_t q) {
    if (const std::optional<Sign> s = difference_sign_if_certain(s_p, s_q, planes_[t].bound)) {
      ++plane_decisions_;
      return *s == Sign::positive;
    }
    // The caller's predicate, when given, needs no exact point or normal.
    if (exact_compare_) {
      const Triangle& tr = tris_[t];
      return exact_compare_(tr.plane[0], tr.plane[1], tr.plane[2], p, q) == Sign::positive;
    }
    return compare_dot(ref(p), ref(q), normal_ref(t)) == Sign::positive;
  }

  // Moves the conflicts in the pool ranges sources_ (except the point skip)
  // to the first of the triangles `targets` that they are strictly above,
  // and finds each target's farthest conflict by comparing <p, n> with
  // <farthest, n>. A point above none of the targets is inside or on the
  // hull and is dropped for good. Each target's list becomes one contiguous
  // range appended to the pool.
  void distribute(std::uint32_t skip, std::span<const std::uint32_t> targets) {
    const auto k = static_cast<std::uint32_t>(targets.size());
    count_.assign(k, 0);
    far_src_.assign(k, none);
    moves_.clear();
    far_value_.resize(k);
    std::uint64_t decided = 0;
    for (auto [b, e] : sources_) {
      live_ -= e - b;
      for (std::uint32_t i = b; i < e; ++i) {
        const std::uint32_t p = pool_[i].point;
        if (p == skip) continue;
        const Coords c = pool_[i].c;
        for (std::uint32_t j = 0; j < k; ++j) {
          const std::uint32_t t = targets[j];
          const PlaneFilter& plane = planes_[t];
          const double s = plane.value(c);
          if (plane.below(s)) {
            ++decided;
            continue;
          }
          if (plane.above(s)) {
            ++decided;
          } else if (plane_orient(t, p) != Sign::positive) {
            continue;
          }
          moves_.push_back({j, i});
          ++count_[j];
          if (far_src_[j] == none || farther(t, s, p, far_value_[j], pool_[far_src_[j]].point)) {
            far_src_[j] = i;
            far_value_[j] = s;
          }
          break;
        }
      }
    }
    plane_decisions_ += decided;
    // Scatter into fresh ranges at the end of the pool.
    std::uint32_t cursor = static_cast<std::uint32_t>(pool_.size());
    if (pool_.size() + moves_.size() >= none)
      throw Error(ErrorCategory::limit, "convex hull: conflict lists exceed 2^32 entries");
    pool_.resize(pool_.size() + moves_.size());
    for (std::uint32_t j = 0; j < k; ++j) {
      Triangle& tr = tris_[targets[j]];
      tr.begin = tr.end = cursor;
      cursor += count_[j];
    }
    for (auto [j, i] : moves_) {
      Triangle& tr = tris_[targets[j]];
      if (i == far_src_[j]) tr.farthest = tr.end - tr.begin;
      pool_[tr.end++] = pool_[i];
    }
    live_ += static_cast<std::uint32_t>(moves_.size());
  }

  // Rewrites the pool with only the live conflict lists once the dead
  // entries outnumber the live ones and the triangles (amortised O(1) per
  // moved entry, memory O(n + triangles)).
  void compact_pool() {
    if (pool_.size() - live_ <= live_ + tris_.size() + 4096) return;
    compact_pool_now();
  }

  // Before the visible triangles' conflicts are appended: when they would
  // outgrow the pool's capacity, the pool is compacted instead. A regrown
  // pool is copied into fresh memory, which glibc's default policy maps anew
  // at every call: half the page faults of an exact hull of 10^4 points in a
  // ball (docs/performance.md's quickhull table). It never regrows here: the live
  // entries only decrease after the first distribution (each step drops its
  // eye), the capacity holds that distribution's n - 4 initial entries and
  // its lists, and after compaction the pool holds the live entries L and
  // the step appends fewer than L. Amortised O(1) per distributed entry (plus
  // the sort): the next compaction comes only after about n more entries
  // were distributed.
  void make_room(std::size_t incoming) {
    if (pool_.size() + incoming > pool_.capacity()) compact_pool_now();
  }

  // The live lists moved to the front of the pool in the order of their
  // ranges, in place: the ranges are disjoint and each moves down, so copying
  // forward is safe. A list's order, and so its farthest entry's offset, is
  // kept. Empty lists are reset to [0, 0), so no range points past the pool.
  void compact_pool_now() {
    live_lists_.clear();
    for (std::uint32_t t = 0; t < tris_.size(); ++t) {
      Triangle& tr = tris_[t];
      if (tr.alive && tr.begin != tr.end)
        live_lists_.push_back(t);
      else
        tr.begin = tr.end = 0;
    }
    std::sort(live_lists_.begin(), live_lists_.end(),
              [this](std::uint32_t a, std::uint32_t b) { return tris_[a].begin < tris_[b].begin; });
    std::uint32_t cursor = 0;
    for (std::uint32_t t : live_lists_) {
      Triangle& tr = tris_[t];
      // A list already in place is left alone (std::copy's output must not
      // begin inside its input).
      if (tr.begin != cursor)
        std::copy(pool_.begin() + tr.begin, pool_.begin() + tr.end, pool_.begin() + cursor);
      tr.end = cursor + (tr.end - tr.begin);
      tr.begin = cursor;
      cursor = tr.end;
    }
    pool_.resize(cursor);
  }

  // Index i of the edge a -> b in triangle t (v[i] == a, v[i+1] == b).
  [[nodiscard]] std::uint32_t edge_index(std::uint32_t t, std::uint32_t a, std::uint32_t b) const {
    const Triangle& tr = tris_[t];
    for (std::uint32_t i = 0; i < 3; ++i)
      if (tr.v[i] == a && tr.v[next3(i)] == b) return i;
    return none;  // unreachable on a consistent triangulation
  }

  // Room for the conflict lists' growth: the pool always holds the n
  // initial conflicts, and after the first distribution is compacted rather
  // than grown (make_room).
  void reserve_for_points() {
    const std::size_t n = n_;
    pool_.reserve(std::max(n, std::min<std::size_t>(2 * n, std::size_t{1} << 21)));
  }

  // Room for more triangles of from_halfspaces' dual points (the only
  // caller with its own exact orient3d) when `used` fill the arrays; other
  // hulls' arrays grow as vectors do. Nearly all dual points are on the
  // hull when few rows are redundant: once past the 4,096 triangles that
  // stay below the huge-page threshold, the arrays take room for all of the
  // 2n − 4 of a hull of all n points (plus a cone) at once, up to what one
  // huge page holds (huge_page_blocks.hpp), then the rest of it; past that
  // they grow as vectors do. Growing through every size costs Sphere5's rows
  // about a fifth of their time; reserving for all n up front would zero
  // huge pages that the small hulls of redundant rows (or of random point
  // clouds) never use, and make those a quarter or more slower.
  void reserve_dual_triangles(std::size_t used) {
    constexpr std::size_t below_threshold = 4096;
    constexpr std::size_t one_huge_page =
        detail::huge_page_bytes / std::max(sizeof(Triangle), sizeof(PlaneFilter));
    const std::size_t whole_hull = 2 * std::size_t{n_} + 8;
    if (used >= whole_hull) return;
    const std::size_t room = used < below_threshold ? std::min(below_threshold, whole_hull)
                                                    : std::min(whole_hull, std::max(2 * used, one_huge_page));
    tris_.reserve(room);
    planes_.reserve(room);
    normal_slot_.reserve(room);
  }

  void build_simplex(const std::uint32_t s[4]) {
    // Orient so that the fourth point is below the face (s0, s1, s2).
    std::uint32_t a = s[0], b = s[1], c = s[2], d = s[3];
    if (orient(a, b, c, d) == Sign::positive) std::swap(b, c);
    // Faces of the tetrahedron a, b, c, d with orient3d(a, b, c, d) < 0,
    // each counterclockwise from outside.
    std::uint32_t t[4] = {new_triangle(a, b, c), new_triangle(a, d, b), new_triangle(b, d, c),
                          new_triangle(c, d, a)};
    for (std::uint32_t i = 0; i < 4; ++i)
      for (std::uint32_t e = 0; e < 3; ++e) {
        std::uint32_t from = tris_[t[i]].v[e], to = tris_[t[i]].v[next3(e)];
        for (std::uint32_t j = 0; j < 4; ++j)
          if (j != i && edge_index(t[j], to, from) != none) tris_[t[i]].nb[e] = t[j];
      }
    for (std::uint32_t p = 0; p < n_; ++p)
      if (p != a && p != b && p != c && p != d) pool_.push_back({coords_[p], p});
    live_ = static_cast<std::uint32_t>(pool_.size());
    sources_.assign(1, {0, live_});
    distribute(none, t);
    for (std::uint32_t i : t)
      if (tris_[i].begin != tris_[i].end) pending_.push_back(i);
  }

  // ---- the main loop --------------------------------------------------------

  void expand() {
    std::uint32_t stamp = 0;
    // First in, first out: the hull grows evenly, so interior points are
    // dropped early (half the predicate calls of last-in-first-out on
    // random balls).
    for (std::size_t next_pending = 0; next_pending < pending_.size(); ++next_pending) {
      // Each point added settles the points it sees: n - live_ grows.
      if (next_pending % eyes_per_report == 0) progress_->reach(n_ - live_);
      std::uint32_t start = pending_[next_pending];
      if (!tris_[start].alive || tris_[start].begin == tris_[start].end) continue;
      const std::uint32_t eye = pool_[tris_[start].begin + tris_[start].farthest].point;
      ++stamp;

      // Visible region by an explicit depth-first search; record each
      // horizon edge from its (unique) visible side.
      visible_.clear();
      horizon_.clear();
      tris_[start].stamp = stamp;
      tris_[start].visible = true;
      stack_.assign(1, start);
      while (!stack_.empty()) {
        std::uint32_t t = stack_.back();
        stack_.pop_back();
        visible_.push_back(t);
        for (std::uint32_t i = 0; i < 3; ++i) {
          std::uint32_t u = tris_[t].nb[i];
          if (tris_[u].stamp != stamp) {
            tris_[u].stamp = stamp;
            const Sign s = side(u, eye);
            tris_[u].visible = s == Sign::positive;
            tris_[u].eye_in_plane = s == Sign::zero;
            if (tris_[u].visible) stack_.push_back(u);
          }
          if (!tris_[u].visible) horizon_.push_back({tris_[t].v[i], tris_[t].v[next3(i)], u});
        }
      }

      // The visible triangles' slots are reused only after their conflicts
      // have moved to the new triangles.
      std::size_t incoming = 0;
      for (std::uint32_t t : visible_) incoming += tris_[t].end - tris_[t].begin;
      make_room(incoming);
      sources_.clear();
      for (std::uint32_t t : visible_)
        if (tris_[t].begin != tris_[t].end) sources_.push_back({tris_[t].begin, tris_[t].end});

      // The cone from the horizon to the eye. start_of_[a] is the new
      // triangle whose horizon edge starts at a. A new triangle against a
      // hidden neighbour whose plane holds the eye lies in that plane, with
      // the same outward side (the neighbour's third corner is below both).
      cone_.clear();
      for (const HorizonEdge& h : horizon_) {
        std::uint32_t t = new_triangle(h.a, h.b, eye);
        if (tris_[h.neighbour].eye_in_plane)
          std::copy(std::begin(tris_[h.neighbour].plane), std::end(tris_[h.neighbour].plane), tris_[t].plane);
        tris_[t].nb[0] = h.neighbour;
        tris_[h.neighbour].nb[edge_index(h.neighbour, h.b, h.a)] = t;
        start_of_at(h.a) = t;
        cone_.push_back(t);
      }
      for (std::uint32_t t : cone_) {
        std::uint32_t u = start_of_at(tris_[t].v[1]);
        tris_[t].nb[1] = u;
        tris_[u].nb[2] = t;
      }

      distribute(eye, cone_);
      for (std::uint32_t t : visible_) kill(t);
      for (std::uint32_t t : cone_)
        if (tris_[t].begin != tris_[t].end) pending_.push_back(t);
      compact_pool();
    }
  }

  std::uint32_t& start_of_at(std::uint32_t p) {
    if (start_of_.empty()) start_of_.assign(n_, none);
    return start_of_[p];
  }

  // ---- maximal facets -------------------------------------------------------

  // Merges coplanar neighbouring triangles into one polygon per plane, drops
  // polygon corners collinear with their neighbours, and numbers the
  // remaining (extreme) points.
  PolygonSoup extract(std::vector<std::uint32_t>* source_index, std::vector<FacePlane>* face_planes) {
    const auto num_tris = static_cast<std::uint32_t>(tris_.size());
    std::vector<std::uint32_t> group(num_tris, none);
    std::vector<std::uint32_t> out_index(n_, none);
    std::vector<std::uint32_t> cycle_next(n_, none);
    PolygonSoup soup;
    std::vector<std::uint32_t> boundary, cycle, corners, extreme_points;

    // The vertex of the triangle across edge i of t that is opposite that edge.
    auto opposite = [&](std::uint32_t t, std::uint32_t i) {
      std::uint32_t u = tris_[t].nb[i];
      std::uint32_t j = edge_index(u, tris_[t].v[next3(i)], tris_[t].v[i]);
      return tris_[u].v[prev3(j)];
    };

    std::uint32_t num_groups = 0;
    for (std::uint32_t seed = 0; seed < num_tris; ++seed) {
      if (!tris_[seed].alive || group[seed] != none) continue;
      const std::uint32_t g = num_groups++;
      boundary.clear();              // pairs (triangle, edge index)
      std::uint32_t witness = none;  // a point strictly below the plane
      group[seed] = g;
      stack_.assign(1, seed);
      while (!stack_.empty()) {
        std::uint32_t t = stack_.back();
        stack_.pop_back();
        for (std::uint32_t i = 0; i < 3; ++i) {
          std::uint32_t u = tris_[t].nb[i];
          if (group[u] == g) continue;
          std::uint32_t o = opposite(t, i);
          if (group[u] == none && (same_plane(seed, u) || side(seed, o) == Sign::zero)) {
            group[u] = g;
            stack_.push_back(u);
          } else {
            // u is in another plane (a different group is never coplanar:
            // it would have been reached through this edge).
            boundary.push_back(t);
            boundary.push_back(i);
            witness = o;
          }
        }
      }

      // The boundary of a convex polygon is one simple cycle.
      for (std::size_t k = 0; k < boundary.size(); k += 2) {
        const Triangle& tr = tris_[boundary[k]];
        cycle_next[tr.v[boundary[k + 1]]] = tr.v[next3(boundary[k + 1])];
      }
      cycle.clear();
      const std::uint32_t first = tris_[boundary[0]].v[boundary[1]];
      std::uint32_t v = first;
      do {
        cycle.push_back(v);
        v = cycle_next[v];
      } while (v != first && cycle.size() <= boundary.size() / 2);

      // A cycle point is a corner iff it is not collinear with its cycle
      // neighbours: (prev, v, next, witness) has orient3d < 0 for a corner
      // of a counterclockwise polygon and 0 on a straight run.
      corners.clear();
      const std::size_t m = cycle.size();
      for (std::size_t k = 0; k < m; ++k) {
        std::uint32_t p = cycle[(k + m - 1) % m], q = cycle[k], r = cycle[(k + 1) % m];
        if (orient(p, q, r, witness) == Sign::zero) continue;
        if (out_index[q] == none) {
          out_index[q] = static_cast<std::uint32_t>(extreme_points.size());
          extreme_points.push_back(q);
        }
        corners.push_back(out_index[q]);
      }
      soup.add_face(corners);
      if (face_planes) {
        const Triangle& tr = tris_[seed];
        face_planes->push_back({tr.plane[0], tr.plane[1], tr.plane[2]});
      }
    }
    // Copied once, in order of first use (growing a vector of rationals
    // would copy them on every reallocation).
    if (copy_points_) {
      soup.points.reserve(extreme_points.size());
      for (std::uint32_t q : extreme_points) soup.points.push_back(exact(q));
    }
    if (source_index) *source_index = std::move(extreme_points);
    return soup;
  }

  std::span<const Vec3> points_;  // exact input (empty for double input)
  bool exact_input_ = false;      // points_ holds the input, else make_exact_ makes it
  std::uint32_t n_ = 0;
  // Hull steps between two progress reports: a millisecond or less.
  static constexpr std::size_t eyes_per_report = 512;
  detail::ProgressReporter silent_{nullptr};
  detail::ProgressReporter* progress_ = &silent_;
  std::span<const Coords> coords_;  // the double approximations
  ScratchVector<Coords> own_coords_;
  double error_ = 0;  // bounds |coords_ - exact| for every coordinate
  PlaneFilterScale scale_;
  // lazy_[p] indexes the approximations made so far and, for approximate
  // input, the exact points made with them.
  std::function<Vec3(std::uint32_t)> make_exact_;
  ScratchVector<std::uint32_t> lazy_;
  std::deque<Vec3> lazy_points_;
  std::deque<ApproxVec3> lazy_approx_;
  ExactOrient exact_orient_;  // the caller's exact orient3d, if any
  ScratchVector<ExactAnswer> answers_;  // exact_answer's slots
  int answer_bits_ = 0;               // log2 of their number
  ExactCompareOrient exact_compare_;  // the caller's exact farther-point test, if any
  bool copy_points_ = true;   // false: the caller knows its points by index
  std::uint64_t plane_decisions_ = 0;  // answers of the filters in this file
  ScratchVector<PlaneFilter> planes_;  // per triangle slot
  ScratchVector<double> far_value_;
  ScratchVector<Conflict> pool_;             // the conflict lists
  ScratchVector<std::uint32_t> live_lists_;  // compaction's scratch
  std::uint32_t live_ = 0;                   // entries of pool_ in live lists
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sources_, moves_;
  ScratchVector<std::uint32_t> count_, far_src_;
  ScratchVector<std::uint32_t> start_of_;
  ScratchVector<Triangle> tris_;
  // Exact normals, only for the few triangle slots whose farthest point
  // needed an exact comparison: normal_slot_[t] indexes them (a deque, as
  // moving rationals around would cost an allocation each).
  ScratchVector<std::uint32_t> normal_slot_;
  std::deque<Vec3> normals_;
  std::deque<ApproxVec3> normal_approx_;
  std::vector<std::uint32_t> free_;
  std::vector<std::uint32_t> pending_;
  std::vector<std::uint32_t> visible_, stack_, cone_;
  std::vector<HorizonEdge> horizon_;
};

}  // namespace

PolygonSoup hull_soup(std::span<const Vec3> points, std::vector<std::uint32_t>* source_index,
                      detail::ProgressReporter* progress) {
  Quickhull qh(points);
  qh.report_to(progress);
  return qh.run(source_index);
}

PolygonSoup hull_soup(std::span<const std::array<double, 3>> points,
                      std::vector<std::uint32_t>* source_index) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(points[i][k]))
        throw Error(ErrorCategory::invalid_argument, "convex hull: point " + std::to_string(i) + " has a " +
                                                         (std::isnan(points[i][k]) ? "NaN" : "infinite") +
                                                         " coordinate " + std::string(1, "xyz"[k]));
  const ApproximatePoints approximate{
      points, 0.0, [&](std::uint32_t i) {
        return Vec3{Rational(points[i][0]), Rational(points[i][1]), Rational(points[i][2])};
      }};
  Quickhull qh(approximate);
  return qh.run(source_index);
}

PolygonSoup hull_soup(const ApproximatePoints& points, std::vector<std::uint32_t>* source_index,
                      detail::ProgressReporter* progress) {
  Quickhull qh(points);
  qh.report_to(progress);
  return qh.run(source_index);
}

PolygonSoup hull_soup(const ApproximatePoints& points, ExactOrient orient, ExactCompareOrient compare,
                      std::vector<std::uint32_t>& source_index, std::vector<FacePlane>* face_planes,
                      detail::ProgressReporter* progress) {
  Quickhull qh(points, std::move(orient), std::move(compare));
  qh.report_to(progress);
  if (face_planes) face_planes->clear();
  return qh.run(&source_index, face_planes);
}

ConvexPolyhedron convex_hull(std::span<const Vec3> points) {
  // The soup already has maximal convex facets and only extreme vertices.
  return detail::trusted_polyhedron(hull_soup(points));
}

ConvexPolyhedron convex_hull(std::span<const Vec3> points, const ProgressCallback& progress) {
  detail::ProgressReporter reporter(detail::callback_of(progress));
  return detail::trusted_polyhedron(hull_soup(points, nullptr, &reporter));
}

ConvexPolyhedron convex_hull(std::span<const std::array<double, 3>> points) {
  return detail::trusted_polyhedron(hull_soup(points));
}

}  // namespace cvms
