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
// Corners are matched by sorting them (never in a hash table, which an
// input can drive quadratic): by a word of their representation, then by
// the exact representation order, a total order in which equal points are
// adjacent; so the grouping costs O(m log m) comparisons for m corners
// whatever the words. Groups are only joined where
// fragments share a corner, never where a corner of one lies on an edge of
// another: that would be sound too, but a group split in two only costs a
// second locate.
#include "translate_side.hpp"

#include <gmp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>

#include "progress_reporter.hpp"
#include "representation_order.hpp"
#include "union_find.hpp"
#include "worker.hpp"

namespace cvms::detail {

namespace {

// A word made of the lowest limbs and sizes of a point's canonical
// numerators and denominators: equal points have equal words, so ordering
// by the word first and the exact representation on ties puts equal points
// together while most comparisons read no limb through a pointer.
std::uint64_t representation_word(const Vec3& p) {
  std::uint64_t word = 0;
  const auto mix = [&](mpz_srcptr z) {
    const std::uint64_t limb = mpz_size(z) > 0 ? mpz_getlimbn(z, 0) : 0;
    const std::uint64_t size = 2 * static_cast<std::uint64_t>(mpz_size(z)) + (mpz_sgn(z) < 0 ? 1 : 0);
    word = (word ^ limb ^ size) * 0x9E3779B97F4A7C15ULL;
    word ^= word >> 29;
  };
  for (int k = 0; k < 3; ++k) {
    mix(p[k].get_num_mpz_t());
    mix(p[k].get_den_mpz_t());
  }
  return word;
}

}  // namespace

std::vector<std::uint32_t> corner_groups(const BoundaryFragments& fragments, std::uint32_t& count) {
  struct Corner {
    std::uint64_t word;
    const Vec3* point;
    std::uint32_t fragment;
  };
  std::size_t total = 0;
  for (const BoundaryFragment& f : fragments.fragments) total += f.corners.size();
  std::vector<Corner> corners;
  corners.reserve(total);
  for (std::uint32_t f = 0; f < fragments.fragments.size(); ++f)
    for (const Vec3& c : fragments.fragments[f].corners) corners.push_back({representation_word(c), &c, f});
  std::sort(corners.begin(), corners.end(), [](const Corner& x, const Corner& y) {
    if (x.word != y.word) return x.word < y.word;
    return RepresentationLess::less(*x.point, *y.point);
  });
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
