// SPDX-License-Identifier: MIT
// The floating-point GJK (Gilbert, Johnson and Keerthi 1988) that proposes
// the exact GJK's warm start (gjk.cpp). Same loop as the exact one, on
// rounded positions and with rounded support walks
// (SupportOperand::approx_support), and the sub-distance by the same
// enumeration of the faces holding the newest point (nearest_on_simplex.cpp),
// in doubles. Rounding may make it stop early, loop without progress or
// pick a wrong face: it stops when the squared distance no longer decreases,
// when the support point is already in the simplex, or after a fixed number
// of steps, and returns whatever simplex it holds. Correctness never
// depends on it: the exact GJK accepts the guess only if the exact
// projection of the origin has positive weights on it, and then still runs
// its exact optimality test (one exact support query per operand when the
// guess is right), continuing exactly from there when it is not.
#include "double_gjk.hpp"

#include <cmath>

namespace cvms::detail {
namespace {

using D3 = std::array<double, 3>;

double ddot(const D3& x, const D3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }

struct Point {
  VertexId va, vb;
  D3 c;
};

struct Simplex {
  std::array<Point, 4> p;
  int size = 0;
  D3 v{};            // the nearest point of the hull, as far as doubles tell
  double vv = 0.0;   // |v|^2
};

// The projection of the origin onto the face {newest} + others by Cramer's
// rule on the Gram system (nearest_on_simplex.cpp has the algebra); false
// if the weights are not all positive or a number is not finite.
bool project(const Simplex& s, unsigned others, D3& v, double& vv, unsigned& mask) {
  const int newest = s.size - 1;
  const D3& w = s.p[newest].c;
  int idx[3];
  int k = 0;
  for (int i = 0; i < newest; ++i)
    if (others & (1u << i)) idx[k++] = i;
  D3 e[3];
  double g[3][3];
  double r[3];
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < 3; ++c) e[i][c] = s.p[idx[i]].c[c] - w[c];
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) g[i][j] = ddot(e[i], e[j]);
    r[i] = -ddot(e[i], w);
  }
  double mu[3] = {0, 0, 0};
  if (k == 1) {
    mu[0] = r[0] / g[0][0];
    if (!(g[0][0] > 0)) return false;
  } else if (k == 2) {
    const double det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
    if (!(det > 0)) return false;
    mu[0] = (r[0] * g[1][1] - g[0][1] * r[1]) / det;
    mu[1] = (g[0][0] * r[1] - r[0] * g[1][0]) / det;
  } else if (k == 3) {
    const auto det3 = [](const double m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double det = det3(g);
    if (!(det > 0)) return false;
    for (int col = 0; col < 3; ++col) {
      double m[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = (j == col) ? r[i] : g[i][j];
      mu[col] = det3(m) / det;
    }
  }
  double rest = 1.0;
  v = w;
  for (int i = 0; i < k; ++i) {
    if (!(mu[i] > 0)) return false;
    rest -= mu[i];
    for (int c = 0; c < 3; ++c) v[c] += mu[i] * e[i][c];
  }
  if (!(rest > 0)) return false;
  vv = ddot(v, v);
  mask = others | (1u << newest);
  return std::isfinite(vv);
}

// s := the face of s nearest to the origin among those holding the newest
// point (the newest alone if rounding rejects every other).
void reduce(Simplex& s) {
  const int newest = s.size - 1;
  D3 best_v = s.p[newest].c;
  double best_vv = ddot(best_v, best_v);
  unsigned best_mask = 1u << newest;
  for (unsigned others = 1; others < (1u << newest); ++others) {
    D3 v;
    double vv = 0.0;
    unsigned mask = 0;
    if (project(s, others, v, vv, mask) && vv < best_vv) {
      best_v = v;
      best_vv = vv;
      best_mask = mask;
    }
  }
  int kept = 0;
  for (int i = 0; i < s.size; ++i)
    if (best_mask & (1u << i)) s.p[kept++] = s.p[i];
  s.size = kept;
  s.v = best_v;
  s.vv = best_vv;
}

Point point_of(const SupportOperand& a, const SupportOperand& b, const D3& offset, VertexId va, VertexId vb) {
  const D3 pa = a.approx_position(va);
  const D3 pb = b.approx_position(vb);
  return {va, vb, {pa[0] - pb[0] - offset[0], pa[1] - pb[1] - offset[1], pa[2] - pb[2] - offset[2]}};
}

bool contains(const Simplex& s, VertexId va, VertexId vb) {
  for (int i = 0; i < s.size; ++i)
    if (s.p[i].va == va && s.p[i].vb == vb) return true;
  return false;
}

GjkCandidate candidate_of(const Simplex& s) {
  GjkCandidate out;
  for (int i = 0; i < s.size; ++i) {
    out.vertex_a[i] = s.p[i].va;
    out.vertex_b[i] = s.p[i].vb;
  }
  out.size = std::isfinite(s.vv) ? s.size : 0;
  return out;
}

// Enough for any pair the exact loop sees in practice (a handful of steps);
// the cap only bounds the time a rounding-induced cycle can waste.
constexpr int max_steps = 64;

}  // namespace

GjkCandidate double_gjk(const SupportOperand& a, const SupportOperand& b, const D3& b_offset, bool until_separated) {
  Simplex s;
  s.p[0] = point_of(a, b, b_offset, VertexId(0), VertexId(0));
  s.size = 1;
  s.v = s.p[0].c;
  s.vv = ddot(s.v, s.v);
  for (int step = 0; step < max_steps && s.vv > 0 && s.size < 4; ++step) {
    const D3 minus_v{-s.v[0], -s.v[1], -s.v[2]};
    const VertexId va = a.approx_support(minus_v, s.p[0].va);
    const VertexId vb = b.approx_support(s.v, s.p[0].vb);
    if (contains(s, va, vb)) break;
    Point w = point_of(a, b, b_offset, va, vb);
    if (until_separated && ddot(s.v, w.c) > 0) break;  // <v, x> > 0 on C, as far as doubles tell
    if (!(s.vv - ddot(s.v, w.c) > 0)) break;  // optimal as far as doubles tell
    const Simplex before = s;
    s.p[s.size++] = w;
    reduce(s);
    if (!(s.vv < before.vv)) {
      s = before;
      break;
    }
  }
  return candidate_of(s);
}

}  // namespace cvms::detail
