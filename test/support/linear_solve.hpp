// SPDX-License-Identifier: MIT
// Small square rational linear systems for the brute-force oracles
// (nearest point on a simplex, the max-slack LP's basic solutions): plain
// Gaussian elimination with exact pivots, public API only.
#pragma once

#include <optional>
#include <vector>

#include "cvms/rational.hpp"

namespace cvms::test {

/// The solution x of g x = r (g square, k × k), nothing if g is singular.
std::optional<std::vector<Rational>> solve_linear(std::vector<std::vector<Rational>> g, std::vector<Rational> r);

}  // namespace cvms::test
