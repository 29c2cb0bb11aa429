// SPDX-License-Identifier: MIT
// Gauss-Jordan elimination, the first nonzero entry of each column as pivot
// (exact, so any nonzero pivot will do).
#include "support/linear_solve.hpp"

#include <utility>

namespace cvms::test {

std::optional<std::vector<Rational>> solve_linear(std::vector<std::vector<Rational>> g, std::vector<Rational> r) {
  const std::size_t k = r.size();
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t pivot = c;
    while (pivot < k && g[pivot][c] == 0) ++pivot;
    if (pivot == k) return std::nullopt;
    std::swap(g[c], g[pivot]);
    std::swap(r[c], r[pivot]);
    for (std::size_t i = 0; i < k; ++i) {
      if (i == c || g[i][c] == 0) continue;
      const Rational f = g[i][c] / g[c][c];
      for (std::size_t j = c; j < k; ++j) g[i][j] -= f * g[c][j];
      r[i] -= f * r[c];
    }
  }
  for (std::size_t i = 0; i < k; ++i) r[i] /= g[i][i];
  return r;
}

}  // namespace cvms::test
