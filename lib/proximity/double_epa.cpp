// SPDX-License-Identifier: MIT
// The floating-point EPA that proposes the exact EPA's support points
// (epa.cpp, "Warm start"). The classic loop (van den Bergen 2001): take the
// face of the polytope nearest to the origin, the support point of M in its
// normal; stop if it is not beyond the face, else replace the faces it sees
// by the cone from it to their horizon. Everything is rounded: a face may be
// misjudged as visible or nearest, the polytope may even lose convexity;
// so it stops at the first sign of trouble (a non-finite number, a support
// point it already has, no horizon) and after a fixed number of steps, and
// all it returns is the list of pairs it added. Those are exact support
// points of M whatever the rounding did (pairs of vertices of A and B), which
// is all the exact EPA needs to use them.
#include "double_epa.hpp"

#include <algorithm>
#include <cmath>

namespace cvms::detail {
namespace {

using D3 = std::array<double, 3>;

double ddot(const D3& x, const D3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
D3 dsub(const D3& x, const D3& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }
D3 dcross(const D3& x, const D3& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

struct Face {
  std::array<int, 3> v;
  D3 n;         // unit outward normal
  double dist;  // <n, v0>
};

class Polytope {
 public:
  Polytope(const SupportOperand& a, const SupportOperand& b) : a_(a), b_(b) {}

  bool start(const std::array<VertexPair, 4>& s) {
    for (const VertexPair& p : s) push(p);
    const double o = ddot(dcross(dsub(pts_[1], pts_[0]), dsub(pts_[2], pts_[0])), dsub(pts_[3], pts_[0]));
    if (!(std::abs(o) > 0) || !std::isfinite(o)) return false;
    const int x = o > 0 ? 1 : 2;
    const int y = o > 0 ? 2 : 1;
    return face(0, y, x) && face(0, 3, y) && face(0, x, 3) && face(x, y, 3);
  }

  // One step; false when it stops.
  bool step(std::vector<VertexPair>& added) {
    const Face* near = nearest();
    if (near == nullptr) return false;
    const D3 n = near->n;
    const double dist = near->dist;
    const VertexId va = a_.approx_support(n, pairs_[near->v[0]].first);
    const D3 minus_n{-n[0], -n[1], -n[2]};
    const VertexId vb = b_.approx_support(minus_n, pairs_[near->v[0]].second);
    const VertexPair w{va, vb};
    if (std::find(pairs_.begin(), pairs_.end(), w) != pairs_.end()) return false;
    const D3 x = point_of(w);
    const double h = ddot(n, x);
    if (!(h - dist > 1e-12 * std::abs(h))) return false;  // not beyond, as far as doubles tell
    if (!insert(w, x)) return false;
    added.push_back(w);
    return true;
  }

 private:
  const SupportOperand& a_;
  const SupportOperand& b_;
  std::vector<D3> pts_;
  std::vector<VertexPair> pairs_;
  std::vector<Face> faces_;
  std::vector<Face> kept_;
  std::vector<std::pair<int, int>> edges_;

  D3 point_of(const VertexPair& p) const { return dsub(a_.approx_position(p.first), b_.approx_position(p.second)); }

  void push(const VertexPair& p) {
    pairs_.push_back(p);
    pts_.push_back(point_of(p));
  }

  bool face(int i, int j, int k) {
    D3 n = dcross(dsub(pts_[j], pts_[i]), dsub(pts_[k], pts_[i]));
    const double len = std::sqrt(ddot(n, n));
    if (!(len > 0) || !std::isfinite(len)) return false;
    for (double& c : n) c /= len;
    faces_.push_back({{i, j, k}, n, ddot(n, pts_[i])});
    return true;
  }

  const Face* nearest() const {
    const Face* best = nullptr;
    for (const Face& f : faces_)
      if (best == nullptr || f.dist < best->dist) best = &f;
    return best;
  }

  // The scratch vectors are members so that their storage is reused.
  bool insert(const VertexPair& w, const D3& x) {
    std::vector<std::pair<int, int>>& edges = edges_;
    std::vector<Face>& kept = kept_;
    edges.clear();
    kept.clear();
    for (const Face& f : faces_) {
      if (ddot(f.n, x) - f.dist > 0) {
        for (int e = 0; e < 3; ++e) edges.emplace_back(f.v[e], f.v[(e + 1) % 3]);
      } else {
        kept.push_back(f);
      }
    }
    if (edges.empty()) return false;
    std::swap(faces_, kept);
    const int n = static_cast<int>(pts_.size());
    pairs_.push_back(w);
    pts_.push_back(x);
    for (const auto& [u, v] : edges)
      if (std::find(edges.begin(), edges.end(), std::pair{v, u}) == edges.end() && !face(u, v, n)) return false;
    return true;
  }
};

// Far more than the exact EPA needs on the benchmark pairs (tens of steps);
// the cap bounds the time a rounding-induced cycle can waste.
constexpr int max_steps = 256;

}  // namespace

std::vector<VertexPair> double_epa(const SupportOperand& a, const SupportOperand& b,
                                   const std::array<VertexPair, 4>& start) {
  std::vector<VertexPair> added;
  Polytope p(a, b);
  if (!p.start(start)) return added;
  for (int i = 0; i < max_steps && p.step(added); ++i) {
  }
  return added;
}

}  // namespace cvms::detail
