// SPDX-License-Identifier: MIT
// The side test of translate_side.hpp.
//
// Why one locate per group: let U = dA + B. For a in dA, a + b has the
// neighbourhood a + B around it (b is interior to B), so dA + b, which is
// the boundary of A + b, lies in the interior of U. Every fragment is a
// closed subset of the boundary of U (the fragments of the pieces' union,
// possibly some left out), so no fragment meets the boundary of A + b.
// Two fragments that share a corner have a connected union; along a chain
// of such fragments the union stays connected and still misses the
// boundary of A + b, so it lies wholly in the interior of A + b or wholly
// outside it. The group's answer is that of any point of it: the centroid
// of its first fragment's first three corners, which lies in that
// fragment's relative interior (the corners are those of a convex polygon
// with no three consecutive ones collinear), located exactly in A after
// the translation by -b.
//
// Corners are matched by sorting them in the exact representation order
// (never by a hash, which an input can make collide), so the grouping costs
// O(m log m) comparisons for m corners. Groups are only joined where
// fragments share a corner, never where a corner of one lies on an edge of
// another: that would be sound too, but a group split in two only costs a
// second locate.
#include "translate_side.hpp"

#include <algorithm>
#include <atomic>

#include "progress_reporter.hpp"
#include "representation_order.hpp"
#include "union_find.hpp"
#include "worker.hpp"

namespace cvms::detail {

std::vector<std::uint32_t> corner_groups(const BoundaryFragments& fragments, std::uint32_t& count) {
  struct Corner {
    const Vec3* point;
    std::uint32_t fragment;
  };
  std::vector<Corner> corners;
  for (std::uint32_t f = 0; f < fragments.fragments.size(); ++f)
    for (const Vec3& c : fragments.fragments[f].corners) corners.push_back({&c, f});
  std::sort(corners.begin(), corners.end(),
            [](const Corner& x, const Corner& y) { return RepresentationLess::less(*x.point, *y.point); });
  UnionFind groups(fragments.fragments.size());
  for (std::size_t i = 1; i < corners.size(); ++i)
    if (*corners[i].point == *corners[i - 1].point) groups.join(corners[i].fragment, corners[i - 1].fragment);
  return groups.numbering(count);
}

std::vector<char> inside_translate(const BoundaryFragments& fragments, const Solid& a, const Vec3& b,
                                   const Options& options) {
  std::uint32_t count = 0;
  const std::vector<std::uint32_t> group = corner_groups(fragments, count);
  // Each group's first fragment (group numbers follow first fragments).
  std::vector<std::uint32_t> first(count);
  for (std::size_t f = group.size(); f-- > 0;) first[group[f]] = static_cast<std::uint32_t>(f);
  constexpr std::size_t chunk = 16;
  std::vector<char> group_inside(count, 0);
  ProgressReporter progress(callback_of(options.progress));
  progress.begin("solid sum: fragments", count);
  std::atomic<std::size_t> next{0};
  run_on_threads(thread_count(options.threads, count / chunk + 1), [&](unsigned) {
    for (std::size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk)) {
      const std::size_t end = std::min<std::size_t>(count, begin + chunk);
      for (std::size_t g = begin; g < end; ++g) {
        const std::vector<Vec3>& c = fragments.fragments[first[g]].corners;
        const Vec3 centroid = Rational(Rational(1) / 3) * (c[0] + c[1] + c[2]);
        group_inside[g] = a.locate(centroid - b) == Location::inside ? 1 : 0;
      }
      progress.advance(end - begin);
    }
  });
  progress.end();
  std::vector<char> inside(group.size());
  for (std::size_t f = 0; f < group.size(); ++f) inside[f] = group_inside[group[f]];
  return inside;
}

}  // namespace cvms::detail
