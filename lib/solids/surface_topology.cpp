// SPDX-License-Identifier: MIT
// The checks of surface_topology.hpp. Edges are matched by sorting their
// vertex pairs (no hashing of input-derived keys, see first_use.hpp).
// Around a vertex v, the outgoing half-edge h = (v, w) of face f is followed
// by the outgoing half-edge of the face g on the other side of (v, w), the
// one after (w, v) in g: on a closed surface whose edges each have two
// faces, this permutes v's outgoing half-edges, and v is a manifold vertex
// iff the permutation is one cycle (one fan).
#include "surface_topology.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "element_names.hpp"

namespace cvms::detail {

namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCategory::topology, message); }

struct HalfEdges {
  std::vector<std::uint32_t> from, to, face, next;
};

HalfEdges half_edges(const FaceLists& faces) {
  HalfEdges h;
  const std::size_t n = faces.corners.size();
  h.from.resize(n);
  h.to.resize(n);
  h.face.resize(n);
  h.next.resize(n);
  for (std::uint32_t f = 0; f + 1 < faces.offsets.size(); ++f) {
    const std::uint32_t begin = faces.offsets[f];
    const std::uint32_t end = faces.offsets[f + 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t j = i + 1 == end ? begin : i + 1;
      h.from[i] = faces.corners[i];
      h.to[i] = faces.corners[j];
      h.face[i] = f;
      h.next[i] = j;
    }
  }
  return h;
}

// twin[i]: the half-edge on the other side of half-edge i.
std::vector<std::uint32_t> match_edges(const HalfEdges& h, std::span<const std::uint32_t> names) {
  const std::size_t n = h.from.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint64_t lo = std::min(h.from[i], h.to[i]);
    const std::uint64_t hi = std::max(h.from[i], h.to[i]);
    keyed[i] = {(lo << 32) | hi, i};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> twin(n);
  for (std::size_t k = 0; k < n;) {
    std::size_t e = k;
    while (e < n && keyed[e].first == keyed[k].first) ++e;
    const std::uint32_t a = keyed[k].second;
    const std::string edge = edge_name(names[h.from[a]], names[h.to[a]]);
    if (e - k == 1)
      fail("open surface: " + edge + " of face " + str(h.face[a]) +
           " has no face on its other side (boundary edge)");
    if (e - k > 2)
      fail(edge + " is shared by " + std::to_string(e - k) + " faces (" + str(h.face[a]) + ", " +
           str(h.face[keyed[k + 1].second]) + ", " + str(h.face[keyed[k + 2].second]) +
           (e - k > 3 ? ", ..." : "") + "): non-manifold edge");
    const std::uint32_t b = keyed[k + 1].second;
    if (h.from[a] == h.from[b])
      fail("faces " + str(std::min(h.face[a], h.face[b])) + " and " + str(std::max(h.face[a], h.face[b])) +
           " both run along " + edge + " in the same direction (inconsistent orientation)");
    twin[a] = b;
    twin[b] = a;
    k = e;
  }
  return twin;
}

void check_fans(const HalfEdges& h, std::span<const std::uint32_t> twin, std::uint32_t num_vertices,
                std::span<const std::uint32_t> names) {
  std::vector<bool> visited(h.from.size(), false);
  std::vector<bool> has_fan(num_vertices, false);
  for (std::uint32_t start = 0; start < h.from.size(); ++start) {
    if (visited[start]) continue;
    const std::uint32_t v = h.from[start];
    if (has_fan[v])
      fail("vertex " + str(names[v]) + ": its faces form more than one fan (non-manifold vertex)");
    has_fan[v] = true;
    for (std::uint32_t e = start; !visited[e]; e = h.next[twin[e]]) visited[e] = true;
  }
}

}  // namespace

void check_closed_manifold(const FaceLists& faces, std::span<const std::uint32_t> names) {
  const HalfEdges h = half_edges(faces);
  const std::vector<std::uint32_t> twin = match_edges(h, names);
  check_fans(h, twin, faces.num_vertices, names);
}

}  // namespace cvms::detail
