// SPDX-License-Identifier: MIT
// from_halfspaces: the exact intersection of half-spaces (halfspaces.hpp
// gives the algorithm). The rows are solved in an affine chart x = o + L·u
// of the smallest flat known to hold the set: all of space at first, one
// dimension less for each implied equality found by the max-slack LP.
//
// Why the dual hull gives the set: with x0 strictly inside, every row reads
// a·(x − x0) <= b − a·x0 with b − a·x0 > 0, i.e. q·y <= 1 for y = x − x0 and
// q = a / (b − a·x0). The set of such y is the polar of Q = conv{q_i}; it is
// bounded iff the origin is interior to Q, its vertices are n/c for the
// facets n·q <= c of Q (c > 0), and a row is irredundant iff its q is a
// vertex of Q. A facet (or the plane of a flat Q) with c <= 0 gives n with
// q_i·n <= 0 for all i: the direction of unboundedness.
//
// In three dimensions a bounded set takes the integer path
// (integer_dual_hull.hpp, intersection_polyhedron.hpp) around a strict
// interior point: the hull decided on homogeneous integer dual points, its
// facets' vertices from the poles of the dual facets' planes (Cramer's rule
// on three tight rows), and the polyhedron read off the dual hull (its
// polar) with its planes taken from the rows. When every row has b > 0 and
// a nonzero normal, the origin is that point and no LP runs: no row can then
// be an implied equality, and the dual hull alone decides boundedness (the
// LP path still runs when it finds the set unbounded, to name the same
// direction as always). Otherwise the point is the LP's, moved to short
// coordinates (short_interior_point.hpp). The result does not depend on the
// point: the polyhedron is the same set, its facets in row order and its
// vertices in order of first use. The rational dual
// hull below runs only for an unbounded set (around the LP's point, to name
// the same direction as always) and in the plane.
#include "cvms/halfspaces.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "homogeneous_dual.hpp"
#include "intersection_polyhedron.hpp"
#include "max_slack_lp.hpp"
#include "progress_reporter.hpp"
#include "short_interior_point.hpp"

namespace cvms {

namespace {

// x = origin + sum_k axes[k] * u_k.
struct Chart {
  Vec3 origin;
  std::vector<Vec3> axes;
};

Chart whole_space() { return {Vec3{0, 0, 0}, {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}}; }

Vec3 to_space(const Chart& chart, const std::vector<Rational>& u) {
  Vec3 x = chart.origin;
  for (std::size_t k = 0; k < chart.axes.size(); ++k) x += u[k] * chart.axes[k];
  return x;
}

Vec3 direction_to_space(const Chart& chart, const std::vector<Rational>& u) {
  Vec3 x{0, 0, 0};
  for (std::size_t k = 0; k < chart.axes.size(); ++k) x += u[k] * chart.axes[k];
  return x;
}

// The rows in the chart's unknowns; a zero row is dropped when it holds and
// makes the result empty (false) when it fails.
bool rows_in_chart(std::span<const HalfspaceRow> rows, const Chart& chart, std::vector<detail::LpRow>& out) {
  out.clear();
  out.reserve(rows.size());
  // A chart of dimension 3 is the identity (whole_space; restrict_chart
  // drops an axis), so its rows are the given ones, with no products.
  const bool identity = chart.axes.size() == 3;
  for (const HalfspaceRow& row : rows) {
    detail::LpRow r;
    r.a.reserve(chart.axes.size());
    bool zero = true;
    for (std::size_t k = 0; k < chart.axes.size(); ++k) {
      r.a.push_back(identity ? row.normal[static_cast<int>(k)] : dot(row.normal, chart.axes[k]));
      zero = zero && sgn(r.a.back()) == 0;
    }
    r.b = identity ? row.offset : row.offset - dot(row.normal, chart.origin);
    if (zero) {
      if (sgn(r.b) < 0) return false;
      continue;
    }
    out.push_back(std::move(r));
  }
  return true;
}

// The chart of the flat where the chart-row a·u == b also holds.
Chart restrict_chart(const Chart& chart, const detail::LpRow& equality) {
  std::size_t k = 0;
  while (sgn(equality.a[k]) == 0) ++k;
  // u_k = (b − sum_{j != k} a_j u_j) / a_k.
  Chart next;
  next.origin = chart.origin + (equality.b / equality.a[k]) * chart.axes[k];
  for (std::size_t j = 0; j < chart.axes.size(); ++j) {
    if (j != k) next.axes.push_back(chart.axes[j] - (equality.a[j] / equality.a[k]) * chart.axes[k]);
  }
  return next;
}

std::vector<Rational> chart_vector(const Vec3& v, std::size_t dimension) {
  std::vector<Rational> u;
  for (std::size_t k = 0; k < dimension; ++k) u.push_back(v[static_cast<int>(k)]);
  return u;
}

// A nonzero vector of the first `dimension` coordinates orthogonal to every
// point of a dual hull that spans less than its dimension (through the
// origin's side, see the file comment).
Vec3 direction_off_flat_hull(const ConvexSet& q, std::size_t dimension) {
  const std::vector<Vec3> v = q.vertices();
  if (dimension == 3 && q.dimension() == 2) return sgn(q.plane_offset()) <= 0 ? q.normal() : -q.normal();
  if (dimension == 3) {
    const Vec3 a = v.front(), b = v.back();
    if (const Vec3 n = cross(a, b); !is_zero(n)) return n;
    return is_zero(cross(a, Vec3{1, 0, 0})) ? Vec3{0, 1, 0} : cross(a, Vec3{1, 0, 0});
  }
  // dimension 2, q a segment or a point in the plane z == 0.
  const Vec3 e = v.back() - v.front();
  if (q.dimension() == 1) {
    const Vec3 n{-e.y, e.x, 0};
    return sgn(dot(n, v.front())) <= 0 ? n : -n;
  }
  return Vec3{-v.front().y, v.front().x, 0};
}

struct DualAnswer {
  std::vector<Vec3> vertices;          // of the set, in chart coordinates (padded with 0)
  std::optional<Vec3> unbounded;       // in chart coordinates
};

// The vertices of {u : rows} around the strict interior point u0, in a chart
// of dimension 2 or 3 (2: everything in the plane z == 0).
DualAnswer dual_vertices(const std::vector<detail::LpRow>& rows, const std::vector<Rational>& u0,
                         std::size_t dimension, const ProgressCallback& progress) {
  std::vector<Vec3> q;
  q.reserve(rows.size());
  for (const detail::LpRow& row : rows) {
    Rational room = row.b;
    Vec3 a{0, 0, 0};
    for (std::size_t k = 0; k < dimension; ++k) {
      room -= row.a[k] * u0[k];
      a[static_cast<int>(k)] = row.a[k];
    }
    q.push_back((1 / room) * a);
  }
  const ConvexSet hull = convex_hull_set(q, progress);
  DualAnswer answer;
  Vec3 center{0, 0, 0};
  for (std::size_t k = 0; k < dimension; ++k) center[static_cast<int>(k)] = u0[k];
  if (hull.empty()) {
    answer.unbounded = Vec3{1, 0, 0};
  } else if (static_cast<std::size_t>(hull.dimension()) < dimension) {
    answer.unbounded = direction_off_flat_hull(hull, dimension);
  } else if (dimension == 3) {
    const ConvexPolyhedron& p = hull.polyhedron();
    for (FaceId f : p.mesh().faces()) {
      if (sgn(p.plane_offset(f)) <= 0) return {{}, p.normal(f)};
      answer.vertices.push_back(center + (1 / p.plane_offset(f)) * p.normal(f));
    }
  } else {
    const std::vector<Vec3> v = hull.vertices();
    const std::vector<Vec3> normals = hull.edge_normals();
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Rational c = dot(normals[i], v[i]);
      if (sgn(c) <= 0) return {{}, normals[i]};
      answer.vertices.push_back(center + (1 / c) * normals[i]);
    }
  }
  return answer;
}

// The full-dimensional case in a chart of dimension 1: an interval.
DualAnswer interval(const std::vector<detail::LpRow>& rows) {
  std::optional<Rational> low, high;
  for (const detail::LpRow& row : rows) {
    const Rational bound = row.b / row.a[0];
    if (sgn(row.a[0]) > 0) {
      if (!high || bound < *high) high = bound;
    } else if (!low || bound > *low) {
      low = bound;
    }
  }
  if (!high) return {{}, Vec3{1, 0, 0}};
  if (!low) return {{}, Vec3{-1, 0, 0}};
  return {{Vec3{*low, 0, 0}, Vec3{*high, 0, 0}}, std::nullopt};
}

// Whether every row has a nonzero normal and holds strictly at the origin
// (then the set has interior there: no LP is needed to find a strict
// interior point).
bool origin_strictly_inside(std::span<const HalfspaceRow> rows) {
  return std::all_of(rows.begin(), rows.end(),
                     [](const HalfspaceRow& row) { return sgn(row.offset) > 0 && !is_zero(row.normal); });
}

std::string text(const Vec3& v) {
  return "(" + to_string(v.x) + ", " + to_string(v.y) + ", " + to_string(v.z) + ")";
}

// The positive multiple of d with coprime integer coordinates: the same
// direction, and the same text whatever scaling the dual hull found it at.
Vec3 primitive(const Vec3& d) {
  mpz_class scale = 1;
  for (int k = 0; k < 3; ++k) mpz_lcm(scale.get_mpz_t(), scale.get_mpz_t(), d[k].get_den_mpz_t());
  Vec3 out = d;
  mpz_class divisor = 0;
  for (int k = 0; k < 3; ++k) {
    out[k] *= scale;
    mpz_gcd(divisor.get_mpz_t(), divisor.get_mpz_t(), out[k].get_num_mpz_t());
  }
  for (int k = 0; k < 3; ++k) out[k] /= divisor;
  return out;
}

// The hulls report their stage "hull" to `progress`, each run afresh.
HalfspaceIntersection intersect_inequalities(std::span<const HalfspaceRow> inequalities,
                                             const ProgressCallback& progress) {
  detail::ProgressReporter reporter(detail::callback_of(progress));
  // Any strict interior point gives the same bounded set, in the documented
  // order (halfspaces.hpp), so when the origin is one the LP is skipped and
  // the rows are dualised as given; an unbounded set still names its
  // direction from the LP's point below, as always.
  bool known_unbounded = false;
  if (!inequalities.empty() && origin_strictly_inside(inequalities)) {
    const std::vector<Rational> origin{Rational(0), Rational(0), Rational(0)};
    if (std::optional<detail::DualVertices> v =
            detail::bounded_vertices(detail::homogeneous_dual(inequalities, origin), &reporter))
      return {ConvexSet(detail::intersection_polyhedron(std::move(*v))), std::nullopt};
    known_unbounded = true;  // whatever the interior point: no second integer hull below
  }
  Chart chart = whole_space();
  std::vector<detail::LpRow> rows;
  for (;;) {
    if (!rows_in_chart(inequalities, chart, rows)) return {};
    const std::size_t dimension = chart.axes.size();
    if (dimension == 0) return {ConvexSet::point(chart.origin), std::nullopt};
    if (rows.empty()) return {ConvexSet(), direction_to_space(chart, chart_vector(Vec3{1, 0, 0}, dimension))};
    const detail::MaxSlack lp = detail::max_slack(rows, static_cast<int>(dimension));
    if (sgn(lp.slack) < 0) return {};
    if (sgn(lp.slack) == 0) {
      chart = restrict_chart(chart, rows[lp.tight.front()]);
      continue;
    }
    // A chart of dimension 3 is all of space (restrict_chart drops an axis).
    if (dimension == 3 && !known_unbounded) {
      if (std::optional<detail::DualVertices> v =
              detail::bounded_vertices(rows, detail::short_interior_point(rows, lp.point), &reporter))
        return {ConvexSet(detail::intersection_polyhedron(std::move(*v))), std::nullopt};
    }
    const DualAnswer dual =
        dimension == 1 ? interval(rows) : dual_vertices(rows, lp.point, dimension, progress);
    if (dual.unbounded) return {ConvexSet(), direction_to_space(chart, chart_vector(*dual.unbounded, dimension))};
    std::vector<Vec3> points;
    points.reserve(dual.vertices.size());
    for (const Vec3& v : dual.vertices) points.push_back(to_space(chart, chart_vector(v, dimension)));
    return {convex_hull_set(points, progress), std::nullopt};
  }
}

}  // namespace

HalfspaceIntersection intersect_halfspaces(std::span<const HalfspaceRow> inequalities) {
  return intersect_halfspaces(inequalities, ProgressCallback());
}

HalfspaceIntersection intersect_halfspaces(std::span<const HalfspaceRow> inequalities,
                                           const ProgressCallback& progress) {
  HalfspaceIntersection answer = intersect_inequalities(inequalities, progress);
  if (answer.unbounded_direction) answer.unbounded_direction = primitive(*answer.unbounded_direction);
  return answer;
}

HalfspaceIntersection intersect_halfspaces(const HalfspaceSystem& system) {
  return intersect_halfspaces(system, ProgressCallback());
}

HalfspaceIntersection intersect_halfspaces(const HalfspaceSystem& system, const ProgressCallback& progress) {
  // The equalities come after the inequalities, so without them the rows
  // are the inequalities as given: no copy (on Sphere5's rows the copy
  // cost a tenth of the intersection).
  if (system.equalities.empty())
    return intersect_halfspaces(std::span<const HalfspaceRow>(system.inequalities), progress);
  std::vector<HalfspaceRow> rows = system.inequalities;
  for (const HalfspaceRow& e : system.equalities) {
    rows.push_back(e);
    rows.push_back({-e.normal, -e.offset});
  }
  return intersect_halfspaces(rows, progress);
}

namespace {

ConvexSet bounded_or_throw(HalfspaceIntersection answer) {
  if (answer.unbounded_direction) {
    throw Error(ErrorCategory::invalid_argument,
                "the half-spaces do not bound their intersection: it is unbounded in direction " +
                    text(*answer.unbounded_direction));
  }
  return std::move(answer.set);
}

}  // namespace

ConvexSet from_halfspaces(std::span<const HalfspaceRow> inequalities) {
  return bounded_or_throw(intersect_halfspaces(inequalities));
}

ConvexSet from_halfspaces(std::span<const HalfspaceRow> inequalities, const ProgressCallback& progress) {
  return bounded_or_throw(intersect_halfspaces(inequalities, progress));
}

ConvexSet from_halfspaces(const HalfspaceSystem& system) { return bounded_or_throw(intersect_halfspaces(system)); }

ConvexSet from_halfspaces(const HalfspaceSystem& system, const ProgressCallback& progress) {
  return bounded_or_throw(intersect_halfspaces(system, progress));
}

ConvexSet from_halfspaces(std::span<const std::array<double, 4>> inequalities) {
  std::vector<HalfspaceRow> rows;
  rows.reserve(inequalities.size());
  for (std::size_t i = 0; i < inequalities.size(); ++i) {
    const auto& r = inequalities[i];
    try {
      rows.push_back({Vec3{rational_from_double(r[0]), rational_from_double(r[1]), rational_from_double(r[2])},
                      rational_from_double(r[3])});
    } catch (const Error&) {
      throw Error(ErrorCategory::invalid_argument,
                  "half-space row " + std::to_string(i) + ": a coefficient is NaN or infinite");
    }
  }
  return from_halfspaces(rows);
}

ConvexSet from_halfspaces(std::span<const std::array<long long, 4>> inequalities) {
  std::vector<HalfspaceRow> rows;
  rows.reserve(inequalities.size());
  for (const auto& r : inequalities) {
    const auto q = [](long long v) { return Rational(std::to_string(v)); };
    rows.push_back({Vec3{q(r[0]), q(r[1]), q(r[2])}, q(r[3])});
  }
  return from_halfspaces(rows);
}

}  // namespace cvms
