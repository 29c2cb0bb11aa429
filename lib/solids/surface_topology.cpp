// SPDX-License-Identifier: MIT
// The check of surface_topology.hpp. Edges are matched by sorting their
// vertex pairs (no hashing of input-derived keys, see first_use.hpp).
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
  std::vector<std::uint32_t> from, to, face;
};

HalfEdges half_edges(const FaceLists& faces) {
  HalfEdges h;
  const std::size_t n = faces.corners.size();
  h.from.resize(n);
  h.to.resize(n);
  h.face.resize(n);
  for (std::uint32_t f = 0; f + 1 < faces.offsets.size(); ++f) {
    const std::uint32_t begin = faces.offsets[f];
    const std::uint32_t end = faces.offsets[f + 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t j = i + 1 == end ? begin : i + 1;
      h.from[i] = faces.corners[i];
      h.to[i] = faces.corners[j];
      h.face[i] = f;
    }
  }
  return h;
}

std::string face_list(const HalfEdges& h, std::span<const std::pair<std::uint64_t, std::uint32_t>> group) {
  std::string list = str(h.face[group[0].second]);
  for (std::size_t i = 1; i < group.size() && i < 3; ++i) list += ", " + str(h.face[group[i].second]);
  return list + (group.size() > 3 ? ", ..." : "");
}

void check_edge(const HalfEdges& h, std::span<const std::pair<std::uint64_t, std::uint32_t>> group,
                std::span<const std::uint32_t> names) {
  const std::uint32_t a = group[0].second;
  const std::string edge = edge_name(names[h.from[a]], names[h.to[a]]);
  if (group.size() == 1)
    fail("open surface: " + edge + " of face " + str(h.face[a]) +
         " has no face on its other side (boundary edge)");
  std::size_t forward = 0;
  for (const auto& [key, i] : group) forward += h.from[i] == h.from[a] ? 1 : 0;
  if (2 * forward == group.size()) return;
  if (group.size() == 2) {
    const std::uint32_t b = group[1].second;
    fail("faces " + str(std::min(h.face[a], h.face[b])) + " and " + str(std::max(h.face[a], h.face[b])) +
         " both run along " + edge + " in the same direction (inconsistent orientation)");
  }
  fail(edge + " is shared by " + std::to_string(group.size()) + " faces (" + face_list(h, group) + "), " +
       std::to_string(std::max(forward, group.size() - forward)) + " of them in the same direction " +
       "(an open or inconsistently oriented surface where parts touch)");
}

}  // namespace

void check_closed_surface(const FaceLists& faces, std::span<const std::uint32_t> names) {
  const HalfEdges h = half_edges(faces);
  const std::size_t n = h.from.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint64_t lo = std::min(h.from[i], h.to[i]);
    const std::uint64_t hi = std::max(h.from[i], h.to[i]);
    keyed[i] = {(lo << 32) | hi, i};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < n;) {
    std::size_t e = k;
    while (e < n && keyed[e].first == keyed[k].first) ++e;
    check_edge(h, std::span(keyed).subspan(k, e - k), names);
    k = e;
  }
}

}  // namespace cvms::detail
