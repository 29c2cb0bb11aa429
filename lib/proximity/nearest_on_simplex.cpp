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
// numerator and no division is needed to test it; and
// since x is orthogonal to every e_i, |x|^2 = <x, w> = <w, w> - sum mu_i r_i.
#include "nearest_on_simplex.hpp"

namespace cvms::detail {
namespace {

// Dot products among the points, computed once: <p_i, p_j>.
struct Dots {
  Rational d[4][4];
  Dots(const std::array<Vec3, 4>& p, int n) {
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j) d[i][j] = d[j][i] = dot(p[i], p[j]);
  }
};

Rational det2(const Rational& a, const Rational& b, const Rational& c, const Rational& d) { return a * d - b * c; }

Rational det3(const Rational g[3][3]) {
  return g[0][0] * det2(g[1][1], g[1][2], g[2][1], g[2][2]) - g[0][1] * det2(g[1][0], g[1][2], g[2][0], g[2][2]) +
         g[0][2] * det2(g[1][0], g[1][1], g[2][0], g[2][1]);
}

// Solves G mu = r for k <= 3 by Cramer's rule: numerators N and D = det G.
void cramer(int k, const Rational g[3][3], const Rational r[3], Rational num[3], Rational& den) {
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
    Rational m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = (j == c) ? r[i] : g[i][j];
    num[c] = det3(m);
  }
}

}  // namespace

SimplexNearest nearest_on_simplex(const std::array<Vec3, 4>& points, int count) {
  const int newest = count - 1;
  const Dots dots(points, count);
  const auto& d = dots.d;
  SimplexNearest best;
  bool found = false;
  // Subsets of the older points; the newest is always in.
  for (std::uint32_t others = 0; others < (1u << newest); ++others) {
    int idx[3];
    int k = 0;
    for (int i = 0; i < newest; ++i)
      if (others & (1u << i)) idx[k++] = i;
    Rational g[3][3];
    Rational r[3];
    for (int i = 0; i < k; ++i) {
      // <e_i, e_j> = <p_i, p_j> - <p_i, w> - <p_j, w> + <w, w>
      for (int j = 0; j < k; ++j) g[i][j] = d[idx[i]][idx[j]] - d[idx[i]][newest] - d[idx[j]][newest] + d[newest][newest];
      r[i] = d[newest][newest] - d[idx[i]][newest];  // -<e_i, w>
    }
    Rational num[3];
    Rational den = 1;
    if (k > 0) {
      cramer(k, g, r, num, den);
      if (sgn(den) <= 0) continue;  // dependent: excluded by the precondition, skipped defensively
    }
    Rational rest = den;
    bool positive = true;
    for (int i = 0; i < k; ++i) {
      positive = positive && sgn(num[i]) > 0;
      rest -= num[i];
    }
    if (!positive || sgn(rest) <= 0) continue;
    // |x|^2 = <w, w> - sum mu_i r_i
    Rational norm = d[newest][newest];
    for (int i = 0; i < k; ++i) norm -= num[i] * r[i] / den;
    if (found && norm >= best.squared_norm) continue;
    found = true;
    best.squared_norm = norm;
    best.support_mask = (others) | (1u << newest);
    for (Rational& w : best.weight) w = 0;
    best.weight[newest] = rest / den;
    for (int i = 0; i < k; ++i) best.weight[idx[i]] = num[i] / den;
  }
  // The newest point alone always qualifies, so `found` holds here.
  best.point = Vec3{0, 0, 0};
  for (int i = 0; i < count; ++i)
    if (best.support_mask & (1u << i)) best.point += best.weight[i] * points[i];
  return best;
}

}  // namespace cvms::detail
