// SPDX-License-Identifier: MIT
// See canonical_view.hpp.
#include "canonical_view.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <span>

#include "cvms/rational.hpp"
#include "dyadic_points.hpp"

namespace cvms::io_detail {
namespace {

// value truncated toward zero to 53 bits, then scaled by ldexp (rounded
// to the nearest subnormal below 2^-1022, the exponent clamped so that
// every value out there gives 0 or infinity): a composition of monotone
// maps, so a strictly smaller double means a strictly smaller value. A
// numerator of one limb is truncated here, without a GMP call.
double approximation(const detail::PackedDyadic& value) {
  const long scale_down = -static_cast<long>(value.exponent);
  if (value.size >= -1 && value.size <= 1) {
    const int drop = std::max(0, static_cast<int>(std::bit_width(value.word)) - 53);
    const double magnitude = static_cast<double>(value.word >> drop << drop);  // exact: 53 bits at most
    const double d = value.size < 0 ? -magnitude : magnitude;
    return std::ldexp(d, static_cast<int>(std::max(scale_down, -4000L)));
  }
  mpz_t view;
  long bits = 0;
  const double d = mpz_get_d_2exp(&bits, value.numerator(view));
  return std::ldexp(d, static_cast<int>(std::clamp(bits + scale_down, -4000L, 4000L)));
}

int compare_exact(const detail::PackedDyadic& a, const detail::PackedDyadic& b, Rational& ra, Rational& rb) {
  // Packings are canonical: equal values have equal packings.
  if (a.size == b.size && a.exponent == b.exponent &&
      std::equal(a.limbs(), a.limbs() + std::max(1, std::abs(a.size)), b.limbs()))
    return 0;
  detail::unpack_dyadic(a, ra);
  detail::unpack_dyadic(b, rb);
  return cmp(ra, rb);
}

// A point's doubles next to its index, so that the sort reads one array.
struct Key {
  std::array<double, 3> approx;
  std::uint32_t index;
};

std::vector<Key> keys_of(const SoupView& soup) {
  std::vector<Key> keys(soup.num_points());
  for (std::uint32_t j = 0; j < keys.size(); ++j) {
    keys[j].index = j;
    for (int k = 0; k < 3; ++k)
      keys[j].approx[static_cast<std::size_t>(k)] = soup.packed != nullptr
                                                        ? approximation(soup.packed->coordinate(j, k))
                                                        : mpq_get_d(soup.points[j][k].get_mpq_t());
  }
  return keys;
}

// The order of positions: by the doubles of (x, y, z), exact on ties.
std::vector<std::uint32_t> point_order(const SoupView& soup) {
  std::vector<Key> keys = keys_of(soup);
  Rational ra;
  Rational rb;
  const auto exact = [&](std::uint32_t a, std::uint32_t b, int k) {
    if (soup.packed != nullptr)
      return compare_exact(soup.packed->coordinate(a, k), soup.packed->coordinate(b, k), ra, rb);
    return cmp(soup.points[a][k], soup.points[b][k]);
  };
  std::sort(keys.begin(), keys.end(), [&](const Key& a, const Key& b) {
    for (int k = 0; k < 3; ++k) {
      const double ka = a.approx[static_cast<std::size_t>(k)];
      const double kb = b.approx[static_cast<std::size_t>(k)];
      if (ka != kb) return ka < kb;
      if (const int c = exact(a.index, b.index, k); c != 0) return c < 0;
    }
    return false;
  });
  std::vector<std::uint32_t> order(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].index;
  return order;
}

}  // namespace

SoupView canonical_view(const SoupView& soup, CanonicalNumbering& numbering) {
  numbering.order = point_order(soup);
  std::vector<std::uint32_t> rank(numbering.order.size());
  for (std::uint32_t i = 0; i < numbering.order.size(); ++i) rank[numbering.order[i]] = i;
  // Each face renumbered and rotated to start at its smallest number, in
  // place in a copy of the index list; then the faces sorted.
  const std::size_t faces = soup.num_faces();
  std::vector<std::uint32_t> renumbered(soup.face_indices.size());
  for (std::size_t f = 0; f < faces; ++f) {
    const std::span<const std::uint32_t> face = soup.face(f);
    const std::span<std::uint32_t> out(renumbered.data() + soup.face_offsets[f], face.size());
    std::transform(face.begin(), face.end(), out.begin(), [&](std::uint32_t v) { return rank[v]; });
    std::rotate(out.begin(), std::min_element(out.begin(), out.end()), out.end());
  }
  const auto face_of = [&](std::uint32_t f) {
    return std::span<const std::uint32_t>(renumbered.data() + soup.face_offsets[f],
                                          soup.face_offsets[f + 1] - soup.face_offsets[f]);
  };
  // Faces are ordered by their first (smallest) number first: a counting
  // sort by it, then a comparison sort of the few faces that share it.
  std::vector<std::uint32_t> start(rank.size() + 1, 0);
  for (std::size_t f = 0; f < faces; ++f) ++start[renumbered[soup.face_offsets[f]] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> face_order(faces);
  for (std::uint32_t f = 0; f < faces; ++f) face_order[start[renumbered[soup.face_offsets[f]]]++] = f;
  const auto less = [&](std::uint32_t a, std::uint32_t b) {
    const auto fa = face_of(a);
    const auto fb = face_of(b);
    return std::lexicographical_compare(fa.begin(), fa.end(), fb.begin(), fb.end());
  };
  for (std::size_t begin = 0; begin < faces;) {
    std::size_t end = begin + 1;
    while (end < faces &&
           renumbered[soup.face_offsets[face_order[end]]] == renumbered[soup.face_offsets[face_order[begin]]])
      ++end;
    std::sort(face_order.begin() + static_cast<std::ptrdiff_t>(begin),
              face_order.begin() + static_cast<std::ptrdiff_t>(end), less);
    begin = end;
  }
  numbering.face_offsets.assign(1, 0);
  numbering.face_offsets.reserve(faces + 1);
  numbering.face_indices.clear();
  numbering.face_indices.reserve(renumbered.size());
  for (std::uint32_t f : face_order) {
    const auto face = face_of(f);
    numbering.face_indices.insert(numbering.face_indices.end(), face.begin(), face.end());
    numbering.face_offsets.push_back(static_cast<std::uint32_t>(numbering.face_indices.size()));
  }
  return {soup.points, numbering.face_offsets, numbering.face_indices, soup.packed, numbering.order};
}

}  // namespace cvms::io_detail
