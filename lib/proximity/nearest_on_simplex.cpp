// SPDX-License-Identifier: MIT
// Exact nearest point of a simplex to the origin (GJK's sub-distance), by
// trying every face that contains the newest point.
//
// Why it is correct. Let W be affinely independent and x* the point of
// conv(W) nearest to the origin; let S be the vertices with positive weight in
// x*'s (unique) barycentric coordinates. Then x* lies in the relative interior
// of conv(S) and minimises |x|^2 there, so the gradient 2 x* is orthogonal to
// aff(S): x* is the projection of the origin onto aff(S), whose barycentric
// coordinates are therefore all positive. Conversely, every face S' whose
// projection has positive coordinates gives a point of conv(W), no nearer than
// x*. So x* is the nearest among the faces whose projections have positive
// coordinates; the unique nearest point also fixes S (relative interiors of
// distinct faces of a simplex are disjoint).
//
// The projection onto aff(S), S = {w, p_1, .., p_k} with e_i = p_i - w: solve
// the Gram system G mu = r, G_ij = <e_i, e_j>, r_i = -<e_i, w>; then x = w +
// sum mu_i e_i, weights mu_i and 1 - sum mu_i. By Cramer's rule mu_i = N_i / D
// with D = det G > 0 (independence), so a weight has the sign of its
// numerator and no division is needed to test it; and since x is orthogonal
// to every e_i, |x|^2 = <x, w> = <w, w> - sum mu_i r_i = (D <w, w> - sum N_i
// r_i) / D.
//
// Integers, not rationals. The barycentric coordinates of the projection do
// not change when every point is scaled by the same positive factor, so the
// points are first multiplied by the lcm L of their coordinates'
// denominators: then every dot product, Gram entry and Cramer numerator is an
// integer, and nothing is reduced by a gcd until the final weights (the
// profile of the rational version was dominated by gcds). Candidates are
// compared by cross-multiplication; |x|^2 is the scaled value over L^2.
//
// Guess in doubles, verify exactly. The face is first chosen in double
// arithmetic (the same enumeration on rounded dot products), and only that
// face is solved exactly; it is accepted iff its exact weights are positive
// and the optimality condition holds exactly: <x, p - x> >= 0 for every point
// p of W, which (x being in conv(W)) makes x the nearest point of conv(W), the
// first-order condition of a convex problem. In the scaled integer frame, with
// Y = D x = sum of the weight numerators times the points, that is
// <Y, P_j> >= D <w, w> - sum N_i r_i for every j. Only if the guess fails
// (rounding chose wrongly) does the exact enumeration run; so the answer never
// depends on the doubles, only the time does.
#include "nearest_on_simplex.hpp"

#include <cmath>

#include "common_denominator.hpp"

namespace cvms::detail {
namespace {

using Int = mpz_class;
struct IntVec {
  Int x, y, z;
};

Int idot(const IntVec& a, const IntVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Int det2(const Int& a, const Int& b, const Int& c, const Int& d) { return a * d - b * c; }

Int det3(const Int g[3][3]) {
  return g[0][0] * det2(g[1][1], g[1][2], g[2][1], g[2][2]) - g[0][1] * det2(g[1][0], g[1][2], g[2][0], g[2][2]) +
         g[0][2] * det2(g[1][0], g[1][1], g[2][0], g[2][1]);
}

// Solves G mu = r for k <= 3 by Cramer's rule: numerators N and D = det G.
void cramer(int k, const Int g[3][3], const Int r[3], Int num[3], Int& den) {
  if (k == 1) {
    den = g[0][0];
    num[0] = r[0];
    return;
  }
  if (k == 2) {
    den = det2(g[0][0], g[0][1], g[1][0], g[1][1]);
    num[0] = det2(r[0], g[0][1], r[1], g[1][1]);
    num[1] = det2(g[0][0], r[0], g[1][0], r[1]);
    return;
  }
  den = det3(g);
  for (int c = 0; c < 3; ++c) {
    Int m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = (j == c) ? r[i] : g[i][j];
    num[c] = det3(m);
  }
}

// The points scaled by the lcm of their denominators, as integers.
Int scale_to_integers(const Vec3* const points[], int count, std::array<IntVec, 4>& out) {
  const Rational* values[12];
  Int scaled[12];
  for (int i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c) values[3 * i + c] = &(*points[i])[c];
  Int l = scale_to_common_denominator(values, static_cast<std::size_t>(3 * count), scaled);
  for (int i = 0; i < count; ++i) {
    out[i].x.swap(scaled[3 * i]);
    out[i].y.swap(scaled[3 * i + 1]);
    out[i].z.swap(scaled[3 * i + 2]);
  }
  return l;
}

struct Candidate {
  std::uint32_t others = 0;  // mask of the older points in the face
  int idx[3] = {0, 0, 0};
  int k = 0;
  Int num[3];
  Int den;
  Int rest;         // D - sum N_i: the newest point's weight numerator
  Int norm_num;     // D <w, w> - sum N_i r_i; scaled |x|^2 = norm_num / den
};


// The exact projection onto the face {newest} + others; false if its weights
// are not all positive (or the face is dependent).
bool solve_face(const Int d[4][4], int newest, std::uint32_t others, Candidate& c) {
  c = Candidate{};
  c.others = others;
  for (int i = 0; i < newest; ++i)
    if (others & (1u << i)) c.idx[c.k++] = i;
  Int g[3][3];
  Int r[3];
  for (int i = 0; i < c.k; ++i) {
    // <e_i, e_j> = <p_i, p_j> - <p_i, w> - <p_j, w> + <w, w>
    for (int j = 0; j < c.k; ++j)
      g[i][j] = d[c.idx[i]][c.idx[j]] - d[c.idx[i]][newest] - d[c.idx[j]][newest] + d[newest][newest];
    r[i] = d[newest][newest] - d[c.idx[i]][newest];  // -<e_i, w>
  }
  c.den = 1;
  if (c.k > 0) {
    cramer(c.k, g, r, c.num, c.den);
    if (sgn(c.den) <= 0) return false;  // dependent: excluded by the precondition, rejected defensively
  }
  c.rest = c.den;
  for (int i = 0; i < c.k; ++i) {
    if (sgn(c.num[i]) <= 0) return false;
    c.rest -= c.num[i];
  }
  if (sgn(c.rest) <= 0) return false;
  c.norm_num = c.den * d[newest][newest];
  for (int i = 0; i < c.k; ++i) c.norm_num -= c.num[i] * r[i];
  return true;
}

// <Y, P_j> >= norm_num for every point j: the exact optimality condition.
bool is_optimal(const Int d[4][4], int count, const Candidate& c) {
  const int newest = count - 1;
  for (int j = 0; j < count; ++j) {
    Int y_dot = c.rest * d[newest][j];
    for (int i = 0; i < c.k; ++i) y_dot += c.num[i] * d[c.idx[i]][j];
    if (y_dot < c.norm_num) return false;
  }
  return true;
}

// The face the double-precision enumeration picks (the mask of the older
// points in it); 0, the newest alone, if nothing qualifies in doubles.
std::uint32_t guess_face(const Int d[4][4], int count) {
  const int newest = count - 1;
  double f[4][4];
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < count; ++j) f[i][j] = d[i][j].get_d();
  std::uint32_t best = 0;
  double best_norm = f[newest][newest];
  for (std::uint32_t others = 1; others < (1u << newest); ++others) {
    int idx[3];
    int k = 0;
    for (int i = 0; i < newest; ++i)
      if (others & (1u << i)) idx[k++] = i;
    double g[3][3];
    double r[3];
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k; ++j) g[i][j] = f[idx[i]][idx[j]] - f[idx[i]][newest] - f[idx[j]][newest] + f[newest][newest];
      r[i] = f[newest][newest] - f[idx[i]][newest];
    }
    double mu[3];
    double det = 0;
    if (k == 1) {
      det = g[0][0];
      mu[0] = r[0] / det;
    } else if (k == 2) {
      det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
      mu[0] = (r[0] * g[1][1] - g[0][1] * r[1]) / det;
      mu[1] = (g[0][0] * r[1] - r[0] * g[1][0]) / det;
    } else {
      auto det3d = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      };
      det = det3d(g);
      for (int col = 0; col < 3; ++col) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) m[i][j] = (j == col) ? r[i] : g[i][j];
        mu[col] = det3d(m) / det;
      }
    }
    if (!(det > 0) || !std::isfinite(det)) continue;
    double rest = 1;
    bool positive = true;
    double norm = f[newest][newest];
    for (int i = 0; i < k; ++i) {
      positive = positive && mu[i] > 0;
      rest -= mu[i];
      norm -= mu[i] * r[i];
    }
    if (!positive || !(rest > 0) || !(norm < best_norm)) continue;
    best = others;
    best_norm = norm;
  }
  return best;
}

// The exact enumeration: the nearest of the faces with positive weights.
Candidate enumerate_faces(const Int d[4][4], int count) {
  const int newest = count - 1;
  Candidate best;
  bool found = false;
  for (std::uint32_t others = 0; others < (1u << newest); ++others) {
    Candidate c;
    if (!solve_face(d, newest, others, c)) continue;
    if (found && c.norm_num * best.den >= best.norm_num * c.den) continue;
    found = true;
    best = std::move(c);
  }
  // The newest point alone always qualifies, so `found` holds here.
  return best;
}

}  // namespace

namespace {

// The answer for the face `best` of the scaled points p.
SimplexNearest answer_of(const Candidate& best, const std::array<IntVec, 4>& p, const Int& scale, int newest) {
  SimplexNearest out;
  out.support_mask = best.others | (1u << newest);
  for (mpz_class& w : out.weight_num) w = 0;
  out.weight_den = best.den;
  IntVec y{best.rest * p[newest].x, best.rest * p[newest].y, best.rest * p[newest].z};
  out.weight_num[newest] = best.rest;
  for (int i = 0; i < best.k; ++i) {
    const int j = best.idx[i];
    out.weight_num[j] = best.num[i];
    y.x += best.num[i] * p[j].x;
    y.y += best.num[i] * p[j].y;
    y.z += best.num[i] * p[j].z;
  }
  // x = Y / (D L), |x|^2 = norm_num / (D L^2)
  const Int dl = best.den * scale;
  out.point = Vec3{Rational(y.x, dl), Rational(y.y, dl), Rational(y.z, dl)};
  for (int c = 0; c < 3; ++c) out.point[c].canonicalize();
  out.squared_norm = Rational(best.norm_num, dl * scale);
  out.squared_norm.canonicalize();
  return out;
}

// The scaled points and their Gram matrix.
Int gram(const SimplexPoints& points, int count, std::array<IntVec, 4>& p, Int d[4][4]) {
  const Int scale = scale_to_integers(points.data(), count, p);
  for (int i = 0; i < count; ++i)
    for (int j = i; j < count; ++j) d[i][j] = d[j][i] = idot(p[i], p[j]);
  return scale;
}

}  // namespace

SimplexNearest nearest_on_simplex(const SimplexPoints& points, int count) {
  const int newest = count - 1;
  std::array<IntVec, 4> p;
  Int d[4][4];
  const Int scale = gram(points, count, p, d);
  Candidate best;
  if (!solve_face(d, newest, guess_face(d, count), best) || !is_optimal(d, count, best)) best = enumerate_faces(d, count);
  return answer_of(best, p, scale, newest);
}

namespace {

// det(a, b, c) into out, with t as scratch: in-place products and
// multiply-adds, so no temporary is allocated.
void det3_into(Int& out, Int& t, const IntVec& a, const IntVec& b, const IntVec& c) {
  t = b.y * c.z;
  t -= b.z * c.y;
  out = a.x * t;
  t = b.x * c.z;
  t -= b.z * c.x;
  out -= a.y * t;
  t = b.x * c.y;
  t -= b.y * c.x;
  out += a.z * t;
}

// Four points: the origin's barycentric coordinates in their tetrahedron,
// by Cramer's rule on the points themselves (the weight of p_i is the
// volume of the tetrahedron with p_i replaced by the origin, over the
// whole one): determinants of the scaled coordinates, half the size of the
// Gram route's, and no projection (aff is all of space).
std::optional<SimplexNearest> inside_tetrahedron(const SimplexPoints& points) {
  std::array<IntVec, 4> p;
  scale_to_integers(points.data(), 4, p);
  SimplexNearest out;
  Int t;
  det3_into(out.weight_num[0], t, p[1], p[2], p[3]);
  det3_into(out.weight_num[1], t, p[0], p[2], p[3]);
  det3_into(out.weight_num[2], t, p[0], p[1], p[3]);
  det3_into(out.weight_num[3], t, p[0], p[1], p[2]);
  mpz_neg(out.weight_num[1].get_mpz_t(), out.weight_num[1].get_mpz_t());
  mpz_neg(out.weight_num[3].get_mpz_t(), out.weight_num[3].get_mpz_t());
  out.weight_den = out.weight_num[0];
  for (int i = 1; i < 4; ++i) out.weight_den += out.weight_num[i];
  const int orientation = sgn(out.weight_den);
  for (const mpz_class& w : out.weight_num)
    if (sgn(w) != orientation || orientation == 0) return std::nullopt;
  if (orientation < 0) {
    for (mpz_class& w : out.weight_num) w = -w;
    out.weight_den = -out.weight_den;
  }
  out.support_mask = 15;
  out.point = Vec3{0, 0, 0};
  out.squared_norm = 0;
  return out;
}

}  // namespace

std::optional<SimplexNearest> project_inside(const SimplexPoints& points, int count) {
  if (count == 4) return inside_tetrahedron(points);
  const int newest = count - 1;
  std::array<IntVec, 4> p;
  Int d[4][4];
  const Int scale = gram(points, count, p, d);
  Candidate c;
  if (!solve_face(d, newest, (1u << newest) - 1, c)) return std::nullopt;
  return answer_of(c, p, scale, newest);
}

Vec3 weighted_sum(const Vec3* const points[], const mpz_class weight_num[], const mpz_class& weight_den, int count) {
  std::array<IntVec, 4> scaled;
  const Int scale = scale_to_integers(points, count, scaled);
  IntVec sum{0, 0, 0};
  for (int i = 0; i < count; ++i) {
    sum.x += weight_num[i] * scaled[i].x;
    sum.y += weight_num[i] * scaled[i].y;
    sum.z += weight_num[i] * scaled[i].z;
  }
  const Int den = weight_den * scale;
  Vec3 out{Rational(sum.x, den), Rational(sum.y, den), Rational(sum.z, den)};
  for (int c = 0; c < 3; ++c) out[c].canonicalize();
  return out;
}

}  // namespace cvms::detail
