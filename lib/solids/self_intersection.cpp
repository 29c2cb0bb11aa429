// SPDX-License-Identifier: MIT
// The search of self_intersection.hpp: every pair of triangles with
// overlapping boxes, in the hierarchy's fixed order, so the pair reported
// for a given input is always the same. Pairs that certified planar facets
// prove apart (planar_facets.hpp) are skipped without an exact test; only
// pairs that do not intersect are skipped, so the first pair found is the
// same as with every pair tested. A facet's verdict on a triangle outside it
// is kept, since a big facet meets the same triangle through many of its own.
#include "self_intersection.hpp"

#include <algorithm>
#include <unordered_map>

#include "planar_facets.hpp"
#include "triangle_intersection.hpp"

namespace cvms::detail {

namespace {

// PlanarFacets::clears for facets of more than one triangle, remembered. A
// one-triangle facet is left to the exact pair test, which costs no more.
class FacetVerdicts {
 public:
  explicit FacetVerdicts(const PlanarFacets& facets) : facets_(facets) {}
  bool clears(std::uint32_t f, std::uint32_t t) {
    if (facets_.size(f) == 1) return false;
    const auto [it, inserted] = known_.try_emplace((std::uint64_t{f} << 32) | t, false);
    if (inserted) it->second = facets_.clears(f, t);
    return it->second;
  }

 private:
  const PlanarFacets& facets_;
  std::unordered_map<std::uint64_t, bool> known_;
};

}  // namespace

SelfIntersection find_self_intersection(const TriangleTree& tree, std::span<const Vec3> points,
                                        std::span<const std::array<std::uint32_t, 3>> triangles,
                                        std::span<const std::uint32_t> face_of) {
  const PlanarFacets facets(points, triangles);
  FacetVerdicts verdicts(facets);
  SelfIntersection result;
  result.candidate_pairs = tree.for_each_overlapping_pair([&](std::uint32_t s, std::uint32_t t) {
    if (face_of[s] == face_of[t]) return false;
    const std::uint32_t fs = facets.of(s), ft = facets.of(t);
    if (fs == ft && facets.certified(fs)) return false;
    if (fs != ft && (verdicts.clears(fs, t) || verdicts.clears(ft, s))) return false;
    if (!triangles_overlap(points, triangles[s], triangles[t])) return false;
    result.faces = std::pair{std::min(face_of[s], face_of[t]), std::max(face_of[s], face_of[t])};
    return true;
  });
  return result;
}

}  // namespace cvms::detail
