// SPDX-License-Identifier: MIT
// homogeneous_hull (homogeneous_hull.hpp). The soup is the one hull_soup
// gives on the rational points: every decision of the quickhull is the exact
// sign of a predicate, whichever stage answers it. The exact stage is the
// integer determinant of homogeneous_orient.cpp, in fixed-width integers
// (fixed_det4.hpp, with the overflow proof) when every coordinate of every
// point has at most 255 bits, each point converted once; in mpz otherwise.
// The quickhull's other exact question, which of two points is farther above
// a triangle, is answered from the same integer determinants
// (homogeneous_compare_orient3d in homogeneous_orient.hpp has the identity,
// fixed_det4_cross_sign in fixed_det4.hpp the overflow proof), so that no
// point is made rational for it.
#include "homogeneous_hull.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <new>
#include <type_traits>

#include "approx.hpp"
#include "filtered_predicates.hpp"
#include "fixed_det4.hpp"
#include "huge_page_blocks.hpp"
#include "hull_soup.hpp"
#include "index_hash.hpp"

namespace cvms::detail {
namespace {

// The points' doubles and one bound for all of them (Approx::of_quotient:
// from the integers' top bits, with no division; mpq_get_d's division made
// them 6 % of from_halfspaces on Sphere5's rows).
struct Approximation {
  std::vector<std::array<double, 3>> coords;
  double max_error = 0;
};

Approximation approximate(const std::vector<HomogeneousPoint>& points) {
  Approximation out;
  out.coords.reserve(points.size());
  for (const HomogeneousPoint& p : points) {
    const mpz_srcptr w = p.w.get_mpz_t();
    const Approx c[3] = {Approx::of_quotient(p.x.get_mpz_t(), w), Approx::of_quotient(p.y.get_mpz_t(), w),
                         Approx::of_quotient(p.z.get_mpz_t(), w)};
    out.coords.push_back({c[0].value, c[1].value, c[2].value});
    for (const Approx& a : c) out.max_error = a.error <= out.max_error ? out.max_error : a.error;
  }
  return out;
}

}  // namespace

Vec3 standing_for(const HomogeneousPoint& p) {
  Vec3 q{Rational(p.x, p.w), Rational(p.y, p.w), Rational(p.z, p.w)};
  for (int m = 0; m < 3; ++m) q[m].canonicalize();
  return q;
}

namespace {

// The widest entry of the points, in signed limbs (fixed_det4.hpp).
int width(const std::vector<HomogeneousPoint>& points) {
  int limbs = 1;
  for (const HomogeneousPoint& p : points)
    for (const mpz_class* v : {&p.x, &p.y, &p.z, &p.w}) limbs = std::max(limbs, signed_limbs(v->get_mpz_t()));
  return limbs;
}

// The last-row cofactors of recent triangles (a, b, c): the quickhull asks
// one triangle about many points (its conflict points, the coplanar
// neighbours when merging facets), and each later question then costs four
// products instead of a 4×4 determinant. An entry is used only for the very
// same ordered triple.
template <int E>
class CofactorCache {
 public:
  // 2^bits entries, at least half as many as points, up to 2^14, in sets of
  // 8 with the least recently used entry replaced. The triangles of one
  // plane share an entry (quickhull.cpp), so fewer planes than points are
  // alive at a time: Sphere5's dual (5,120 points) asks about 2,925 planes,
  // each computed once with an unbounded cache. A direct-mapped cache
  // recomputes many of them (conflicts evict planes in use); 8 ways compute
  // fewer (16 ways gain little more, 2 ways about half as much). Every
  // entry is 340 bytes (E = 3) of memory first touched in the call, so the
  // entries are one scratch block on huge pages (huge_page_blocks.hpp) from
  // 256 KiB on (E = 3: 2^10 entries), which the kernel zeroes 2 MiB at a
  // time on first use, one fault each: on 4 KiB pages a larger cache costs
  // more in page faults than it saves in cofactors. On huge pages the faults
  // a call are the same for 2^12 and 2^14 entries, and 2^14 recompute far
  // fewer evicted planes (on Sphere6's facet planes, about a sixth fewer
  // instructions for the whole from_halfspaces). Only the keys are cleared;
  // the cofactors are written when first used (zeroing them all would be a
  // large share of a small intersection, mostly page faults), and the keys
  // are not taken from calloc, whose memory the kernel zeroes page by page.
  // The recency clock may wrap
  // after 2^32 questions: that only makes a worse choice of entry to
  // replace. A returned reference is valid until the next call (which may
  // replace its entry); every caller uses it within one expression.
  explicit CofactorCache(std::size_t points)
      : set_bits_(set_bits_for(points)), keys_(entries(set_bits_)), values_(entries(set_bits_)) {}

  const Cofactors<E>& cofactors(std::uint32_t a, std::uint32_t b, std::uint32_t c,
                                const ScratchVector<FixedRow<E>>& rows) {
    const std::size_t first = index_slot(set_bits_, a, b, c) << kWayBits;
    ++clock_;
    std::size_t victim = first;
    for (std::size_t i = first; i < first + kWays; ++i) {
      Key& key = keys_[i];
      if (key.used && key.a == a && key.b == b && key.c == c) {
        key.stamp = clock_;
        return *std::launder(static_cast<Cofactors<E>*>(static_cast<void*>(values_[i].bytes)));
      }
      if (!key.used || (keys_[victim].used && key.stamp < keys_[victim].stamp)) victim = i;
    }
    keys_[victim] = {true, a, b, c, clock_};
    return *::new (values_[victim].bytes) Cofactors<E>(last_row_cofactors<E>(rows[a], rows[b], rows[c]));
  }

 private:
  static constexpr int kWayBits = 3;
  static constexpr std::size_t kWays = std::size_t{1} << kWayBits;
  static_assert(std::is_trivially_copyable_v<Cofactors<E>> && std::is_trivially_destructible_v<Cofactors<E>>);
  struct Key {
    bool used = false;
    std::uint32_t a = 0, b = 0, c = 0, stamp = 0;
  };
  // Uninitialised storage for one entry's cofactors.
  struct Slot {
    alignas(Cofactors<E>) unsigned char bytes[sizeof(Cofactors<E>)];
  };
  static int set_bits_for(std::size_t points) { return std::max(cache_bits(points, 2, 14) - kWayBits, 1); }
  static std::size_t entries(int set_bits) { return std::size_t{1} << (set_bits + kWayBits); }

  int set_bits_;
  std::uint32_t clock_ = 0;
  std::vector<Key> keys_;                           // at most 320 KiB
  HugePageArray<Slot, BlockLife::scratch> values_;  // left unwritten
};

// y = the pole of the plane of points i, j, k from their cofactors
// (homogeneous_hull.hpp).
template <int E>
void pole_from(const Cofactors<E>& c, HomogeneousPoint& y) {
  mpz_class* coordinate[4] = {&y.x, &y.y, &y.z, &y.w};
  for (int m = 0; m < 4; ++m) assign_to(coordinate[m]->get_mpz_t(), c[static_cast<std::size_t>(m)], m < 3);
}

// hull_soup with the exact stages given, and, when face_poles is asked for,
// the pole of each face's plane triple by pole_of(i, j, k, y), written into
// one scratch point whose limbs are reused and stored from there.
template <class PoleOf>
PolygonSoup hull_with_poles(const ApproximatePoints& approx, const ExactOrient& orient,
                            const ExactCompareOrient& compare, std::vector<std::uint32_t>& source_index,
                            FacePoles* face_poles, const PoleOf& pole_of, ProgressReporter* progress) {
  if (!face_poles) return hull_soup(approx, orient, compare, source_index, nullptr, progress);
  std::vector<std::array<std::uint32_t, 3>> planes;
  PolygonSoup soup = hull_soup(approx, orient, compare, source_index, &planes, progress);
  *face_poles = FacePoles();
  face_poles->poles.reserve(planes.size());
  HomogeneousPoint y;
  for (const auto& [i, j, k] : planes) {
    pole_of(i, j, k, y);
    HomogeneousPoint& stored = face_poles->poles.emplace_back();
    face_poles->limbs.store(stored.x, y.x.get_mpz_t());
    face_poles->limbs.store(stored.y, y.y.get_mpz_t());
    face_poles->limbs.store(stored.z, y.z.get_mpz_t());
    face_poles->limbs.store(stored.w, y.w.get_mpz_t());
  }
  return soup;
}

// The hull with every undecided orient3d as the integer determinant of
// homogeneous_orient.cpp (sign orient3d = −sign det), each point converted
// to E limbs once instead of at every call, and each triangle's last-row
// cofactors cached, from which the poles come too.
template <int E>
PolygonSoup hull_in_width(const std::vector<HomogeneousPoint>& points, const ApproximatePoints& approx,
                          std::vector<std::uint32_t>& source_index, FacePoles* face_poles,
                          ProgressReporter* progress) {
  ScratchVector<FixedRow<E>> rows;
  rows.reserve(points.size());
  for (const HomogeneousPoint& p : points)
    rows.push_back(fixed_row<E>({p.x.get_mpz_t(), p.y.get_mpz_t(), p.z.get_mpz_t(), p.w.get_mpz_t()}));
  CofactorCache<E> cache(points.size());
  const ExactOrient orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    ++predicate_counters().exact;
    return sign_of(-fixed_det4_sign<E>(cache.cofactors(a, b, c, rows), rows[d]));
  };
  // orient3d(a, b, c, p) − orient3d(a, b, c, q) has the sign of
  // −(Δ_p q.w − Δ_q p.w) (homogeneous_orient.hpp).
  const ExactCompareOrient compare = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t p,
                                         std::uint32_t q) {
    ++predicate_counters().exact;
    return sign_of(-fixed_det4_cross_sign<E>(cache.cofactors(a, b, c, rows), rows[p], rows[q]));
  };
  return hull_with_poles(approx, orient, compare, source_index, face_poles,
                         [&](std::uint32_t i, std::uint32_t j, std::uint32_t k, HomogeneousPoint& y) {
                           pole_from<E>(cache.cofactors(i, j, k, rows), y);
                         },
                         progress);
}

mpz_class dot(const std::array<mpz_class, 3>& u, const HomogeneousPoint& p) { return u[0] * p.x + u[1] * p.y + u[2] * p.z; }

std::array<mpz_class, 3> cross(const HomogeneousPoint& p, const HomogeneousPoint& q) {
  return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x};
}

// y = the pole of the plane of points i, j, k by Cramer's rule in mpz
// (homogeneous_hull.hpp), for entries too long for the fixed widths.
void mpz_pole(const std::vector<HomogeneousPoint>& points, std::uint32_t i, std::uint32_t j, std::uint32_t k,
              HomogeneousPoint& y) {
  const HomogeneousPoint &a = points[i], &b = points[j], &c = points[k];
  const std::array<mpz_class, 3> bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  y.w = dot(bc, a);
  mpz_class* coordinate[3] = {&y.x, &y.y, &y.z};
  for (std::size_t m = 0; m < 3; ++m) *coordinate[m] = a.w * bc[m] + b.w * ca[m] + c.w * ab[m];
}

}  // namespace

PolygonSoup homogeneous_hull(const std::vector<HomogeneousPoint>& points, const std::function<Vec3(std::uint32_t)>& exact,
                             std::vector<std::uint32_t>& source_index, FacePoles* face_poles,
                             ProgressReporter* progress) {
  const Approximation approx = approximate(points);
  const ApproximatePoints approximate_points{approx.coords, approx.max_error, exact};
  switch (width(points)) {
    case 1: return hull_in_width<1>(points, approximate_points, source_index, face_poles, progress);
    case 2: return hull_in_width<2>(points, approximate_points, source_index, face_poles, progress);
    case 3: return hull_in_width<3>(points, approximate_points, source_index, face_poles, progress);
    case 4: return hull_in_width<4>(points, approximate_points, source_index, face_poles, progress);
    default: break;
  }
  const ExactOrient orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    return homogeneous_orient3d(points[a], points[b], points[c], points[d]);
  };
  const ExactCompareOrient compare = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t p,
                                         std::uint32_t q) {
    return homogeneous_compare_orient3d(points[a], points[b], points[c], points[p], points[q]);
  };
  return hull_with_poles(approximate_points, orient, compare, source_index, face_poles,
                         [&](std::uint32_t i, std::uint32_t j, std::uint32_t k, HomogeneousPoint& y) {
                           mpz_pole(points, i, j, k, y);
                         },
                         progress);
}

}  // namespace cvms::detail
