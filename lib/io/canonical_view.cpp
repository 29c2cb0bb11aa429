// SPDX-License-Identifier: MIT
// See canonical_view.hpp.
#include "canonical_view.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <span>

#include "cvms/rational.hpp"
#include "dyadic_points.hpp"

namespace cvms::io_detail {
namespace {

// value truncated toward zero to 53 bits, then scaled: the exponent clamped
// so that ldexp neither wraps nor leaves the range (out there every value
// gives 0 or infinity). Monotone in the value: a strictly smaller double
// means a strictly smaller value.
double approximation(const detail::PackedDyadic& value) {
  mpz_t view;
  long bits = 0;
  const double d = mpz_get_d_2exp(&bits, value.numerator(view));
  const long scale = std::clamp(bits - static_cast<long>(value.exponent), -4000L, 4000L);
  return std::ldexp(d, static_cast<int>(scale));
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

// The order of positions: by the doubles of (x, y, z), exact on ties.
std::vector<std::uint32_t> point_order(const SoupView& soup) {
  const std::size_t n = soup.num_points();
  std::vector<std::array<double, 3>> keys(n);
  for (std::size_t j = 0; j < n; ++j)
    for (int k = 0; k < 3; ++k)
      keys[j][static_cast<std::size_t>(k)] =
          soup.packed != nullptr ? approximation(soup.packed->coordinate(j, k)) : mpq_get_d(soup.points[j][k].get_mpq_t());
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  Rational ra;
  Rational rb;
  const auto exact = [&](std::uint32_t a, std::uint32_t b, int k) {
    if (soup.packed != nullptr) return compare_exact(soup.packed->coordinate(a, k), soup.packed->coordinate(b, k), ra, rb);
    return cmp(soup.points[a][k], soup.points[b][k]);
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k) {
      const double ka = keys[a][static_cast<std::size_t>(k)];
      const double kb = keys[b][static_cast<std::size_t>(k)];
      if (ka != kb) return ka < kb;
      if (const int c = exact(a, b, k); c != 0) return c < 0;
    }
    return false;
  });
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
  std::vector<std::uint32_t> face_order(faces);
  std::iota(face_order.begin(), face_order.end(), std::uint32_t{0});
  std::sort(face_order.begin(), face_order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const auto fa = face_of(a);
    const auto fb = face_of(b);
    return std::lexicographical_compare(fa.begin(), fa.end(), fb.begin(), fb.end());
  });
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
