// SPDX-License-Identifier: MIT
// The pairing and the splitting of manifold_split.hpp.
//
// Pairing around an edge (u, v) with axis e = v - u: a triangle (u, v, w)
// has normal e x (w - u), which points to the side reached from its
// half-plane by a positive turn about e, so the solid it bounds (behind it)
// lies on the negative side, up to the next triangle turning negatively.
// That triangle bounds the same wedge of solid, from the other side: it runs
// v to u. Triangles are sorted by their angle about e from the first one's
// half-plane: the sign of det[e, w0 - u, w - u] splits the turn into
// halves, a zero with dot((e x (w0 - u)), (e x (w - u))) < 0 is the opposite
// half-plane, and within a half w1 comes before w2 when
// det[e, w1 - u, w2 - u] > 0. Each triangle running u to v is paired with
// the one before it.
//
// Fans: the corners of the triangles at one vertex are joined when their
// triangles are paired across an edge at that vertex; each class is a fan
// (a disk's worth of triangles around the point). The class with the
// smallest corner keeps the vertex; each other class gets a new index, in
// order of its smallest corner, so the numbering is deterministic.
#include "manifold_split.hpp"

#include <algorithm>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "union_find.hpp"

namespace cvms::detail {

namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

using Edge = std::pair<std::uint32_t, std::uint32_t>;

std::uint32_t from_of(const Triangles& t, std::uint32_t h) { return t[h / 3][h % 3]; }
std::uint32_t to_of(const Triangles& t, std::uint32_t h) { return t[h / 3][(h % 3 + 1) % 3]; }
std::uint32_t far_of(const Triangles& t, std::uint32_t h) { return t[h / 3][(h % 3 + 2) % 3]; }

// Every half-edge h = 3 t + i (corner i to corner i + 1 of t) with the key
// of its edge (its two indices, smaller first), sorted by key.
std::vector<std::pair<std::uint64_t, std::uint32_t>> edge_keys(const Triangles& tris) {
  const auto n = static_cast<std::uint32_t>(tris.size() * 3);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::uint32_t h = 0; h < n; ++h) {
    const std::uint64_t a = from_of(tris, h);
    const std::uint64_t b = to_of(tris, h);
    keyed[h] = {(std::min(a, b) << 32) | std::max(a, b), h};
  }
  std::sort(keyed.begin(), keyed.end());
  return keyed;
}

class EdgeAngles {
 public:
  EdgeAngles(const std::vector<Vec3>& p, std::uint32_t u, std::uint32_t v, std::uint32_t w0)
      : p_(p), u_(p[u]), e_(p[v] - p[u]), r0_(p[w0] - p[u]) {}

  bool before(std::uint32_t w1, std::uint32_t w2) const {
    const Vec3 r1 = p_[w1] - u_;
    const Vec3 r2 = p_[w2] - u_;
    const int h1 = half(r1);
    const int h2 = half(r2);
    if (h1 != h2) return h1 < h2;
    return sign_triple(e_, r1, r2) == Sign::positive;
  }

 private:
  // 0: the first half-plane, 1: turning positively, 2: opposite, 3: negatively.
  int half(const Vec3& r) const {
    const Sign s = sign_triple(e_, r0_, r);
    if (s == Sign::positive) return 1;
    if (s == Sign::negative) return 3;
    return sign_dot(cross(e_, r0_), cross(e_, r)) == Sign::positive ? 0 : 2;
  }

  const std::vector<Vec3>& p_;
  const Vec3& u_;
  Vec3 e_, r0_;
};

// partner[h] for every half-edge h = 3 t + i (corner i to corner i + 1 of t);
// `bad` set to an edge whose triangles do not alternate in direction.
std::vector<std::uint32_t> pair_half_edges(const std::vector<Vec3>& vertices, const Triangles& tris,
                                           std::optional<Edge>& bad) {
  const auto n = static_cast<std::uint32_t>(tris.size() * 3);
  const auto keyed = edge_keys(tris);
  std::vector<std::uint32_t> partner(n);
  std::vector<std::uint32_t> group;
  for (std::size_t k = 0; k < n;) {
    std::size_t e = k;
    group.clear();
    for (; e < n && keyed[e].first == keyed[k].first; ++e) group.push_back(keyed[e].second);
    k = e;
    const std::uint32_t u = from_of(tris, group[0]);
    const std::uint32_t v = to_of(tris, group[0]);
    if (group.size() % 2 != 0) {
      bad = Edge{u, v};
      return partner;
    }
    if (group.size() > 2) {
      const EdgeAngles angles(vertices, u, v, far_of(tris, group[0]));
      std::sort(group.begin() + 1, group.end(),
                [&](std::uint32_t x, std::uint32_t y) { return angles.before(far_of(tris, x), far_of(tris, y)); });
    }
    for (std::size_t i = 0; i < group.size(); ++i) {
      const std::uint32_t h = group[i];
      if (from_of(tris, h) != u) continue;
      const std::uint32_t g = group[(i + group.size() - 1) % group.size()];
      if (from_of(tris, g) != v) {
        bad = Edge{u, v};
        return partner;
      }
      partner[h] = g;
      partner[g] = h;
    }
  }
  return partner;
}

// The corners joined across the partner pairs, except at the start of the
// half-edges `cut` marks; each class after the first at a vertex gets a new
// index (a copy of the point).
void renumber(std::vector<Vec3>& vertices, Triangles& triangles, const std::vector<std::uint32_t>& partner,
              const std::vector<bool>& cut) {
  const auto n = static_cast<std::uint32_t>(triangles.size() * 3);
  // Corner c = 3 t + i is corner i of triangle t; half-edge h starts at corner h.
  UnionFind fans(n);
  const auto next_corner = [](std::uint32_t c) { return c - c % 3 + (c % 3 + 1) % 3; };
  for (std::uint32_t h = 0; h < n; ++h)
    if (!cut[h]) fans.join(h, next_corner(partner[h]));  // both at the start of h
  std::vector<std::uint32_t> index_of_class(n, UINT32_MAX);
  std::vector<bool> vertex_claimed(vertices.size(), false);
  for (std::uint32_t c = 0; c < n; ++c) {
    std::uint32_t& index = index_of_class[fans.find(c)];
    const std::uint32_t v = triangles[c / 3][c % 3];
    if (index != UINT32_MAX) continue;
    if (!vertex_claimed[v]) {
      vertex_claimed[v] = true;
      index = v;
    } else {
      index = static_cast<std::uint32_t>(vertices.size());
      vertices.push_back(vertices[v]);
    }
  }
  for (std::uint32_t c = 0; c < n; ++c) triangles[c / 3][c % 3] = index_of_class[fans.find(c)];
}

// The half-edges whose edge (by index) still has more than two triangles,
// marked at those that start at the edge's smaller index.
std::vector<bool> crowded_edge_starts(const Triangles& tris) {
  const auto n = static_cast<std::uint32_t>(tris.size() * 3);
  const auto keyed = edge_keys(tris);
  std::vector<bool> cut(n, false);
  for (std::size_t k = 0; k < n;) {
    std::size_t e = k;
    while (e < n && keyed[e].first == keyed[k].first) ++e;
    if (e - k > 2)
      for (std::size_t j = k; j < e; ++j) {
        const std::uint32_t h = keyed[j].second;
        cut[h] = from_of(tris, h) < to_of(tris, h);
      }
    k = e;
  }
  return cut;
}

}  // namespace

// Two passes: the first gives each fan its own index. A fan that runs
// through the same crowded edge (u, v) more than once (the parts touching
// along it are joined around u and around v as well) is still one class; the
// second pass cuts such fans at u where they cross that edge: each arc
// between two crossings closes on the edge from the copy of u to v, its
// first triangle leaving along it and its last arriving along it, so every
// edge then has two triangles in opposite directions.
std::optional<Edge> try_split_non_manifold(std::vector<Vec3>& vertices, Triangles& triangles) {
  std::optional<Edge> bad;
  const std::vector<std::uint32_t> partner = pair_half_edges(vertices, triangles, bad);
  if (bad) return bad;
  renumber(vertices, triangles, partner, std::vector<bool>(triangles.size() * 3, false));
  const std::vector<bool> cut = crowded_edge_starts(triangles);
  if (std::find(cut.begin(), cut.end(), true) == cut.end()) return std::nullopt;
  renumber(vertices, triangles, partner, cut);
  const std::vector<bool> left = crowded_edge_starts(triangles);
  const auto h = static_cast<std::uint32_t>(std::find(left.begin(), left.end(), true) - left.begin());
  if (h == left.size()) return std::nullopt;
  return Edge{from_of(triangles, h), to_of(triangles, h)};
}

void split_non_manifold(std::vector<Vec3>& vertices, Triangles& triangles) {
  if (try_split_non_manifold(vertices, triangles))
    throw Error(ErrorCategory::invalid_argument,
                "assemble_boundary: the triangles around an edge do not bound a solid");
}

}  // namespace cvms::detail
