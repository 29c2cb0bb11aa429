// SPDX-License-Identifier: MIT
// See canonical_order.hpp.
#include "canonical_order.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

namespace cvms::cli {

PolygonSoup canonical_soup(const ConvexPolyhedron& p) {
  PolygonSoup soup = p.to_soup();
  std::vector<std::uint32_t> order(soup.points.size());
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  // Vec3's operator< is the exact lexicographic order: an order of numbers,
  // not a geometric decision, so no predicate is needed.
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return soup.points[a] < soup.points[b]; });
  std::vector<std::uint32_t> rank(order.size());
  PolygonSoup canonical;
  canonical.points.reserve(order.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = i;
    canonical.points.push_back(std::move(soup.points[order[i]]));
  }
  // Each facet renumbered and rotated to start at its smallest number (a
  // rotation keeps its orientation), then the facets sorted.
  std::vector<std::vector<std::uint32_t>> faces(soup.num_faces());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (std::uint32_t v : soup.face(f)) faces[f].push_back(rank[v]);
    std::rotate(faces[f].begin(), std::min_element(faces[f].begin(), faces[f].end()), faces[f].end());
  }
  std::sort(faces.begin(), faces.end());
  canonical.face_indices.reserve(soup.face_indices.size());
  for (const std::vector<std::uint32_t>& face : faces)
    canonical.add_face(std::span<const std::uint32_t>(face));
  return canonical;
}

}  // namespace cvms::cli
