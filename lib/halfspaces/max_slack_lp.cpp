// SPDX-License-Identifier: MIT
// The max-slack LP of max_slack_lp.hpp by the dictionary form of the simplex
// method (Chvátal, "Linear Programming", ch. 2-3) in exact rationals.
//
// Shape: the free unknowns are split, u = p − q with p, q >= 0, and the
// slack is shifted, t = t' − M with M = max(0, −min b_i), so that every
// right-hand side b_i + M (and the bound 1 + M on t') is >= 0 and the origin
// is a feasible basis: one phase suffices. Bland's rule (smallest index
// enters and leaves) excludes cycling, so the method terminates; the
// objective t' is bounded by 1 + M, so it ends at an optimum. The dictionary
// has one row per constraint and only 2d + 1 <= 7 columns, so a pivot costs
// O(7 m) rational operations.
#include "max_slack_lp.hpp"

#include <limits>

namespace cvms::detail {

namespace {

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

// basic_k = constant + sum_j coef[j] * nonbasic_j, for every basic variable.
struct Dictionary {
  std::vector<Rational> constant;
  std::vector<std::vector<Rational>> coef;
  std::vector<std::size_t> basic;     // variable index of each row
  std::vector<std::size_t> nonbasic;  // variable index of each column
  Rational objective;                 // the objective's constant
  std::vector<Rational> objective_coef;
};

// Variables: p_0..p_{d-1}, q_0..q_{d-1}, t' (structural), then one slack
// per constraint row (the last constraint is t' <= 1 + M).
Dictionary initial_dictionary(const std::vector<LpRow>& rows, int d, const Rational& shift) {
  const std::size_t columns = 2 * static_cast<std::size_t>(d) + 1;
  Dictionary dict;
  for (std::size_t j = 0; j < columns; ++j) dict.nonbasic.push_back(j);
  dict.objective_coef.assign(columns, Rational(0));
  dict.objective_coef[columns - 1] = 1;
  for (std::size_t i = 0; i <= rows.size(); ++i) {
    std::vector<Rational> coef(columns, Rational(0));
    if (i < rows.size()) {
      for (int k = 0; k < d; ++k) {
        coef[static_cast<std::size_t>(k)] = -rows[i].a[static_cast<std::size_t>(k)];
        coef[static_cast<std::size_t>(d + k)] = rows[i].a[static_cast<std::size_t>(k)];
      }
      dict.constant.push_back(rows[i].b + shift);
    } else {
      dict.constant.push_back(1 + shift);
    }
    coef[columns - 1] = -1;
    dict.coef.push_back(std::move(coef));
    dict.basic.push_back(columns + i);
  }
  return dict;
}

// Bland: the entering column with a positive objective coefficient whose
// variable index is smallest; none at an optimum.
std::size_t entering_column(const Dictionary& dict) {
  std::size_t best = none;
  for (std::size_t j = 0; j < dict.nonbasic.size(); ++j) {
    if (sgn(dict.objective_coef[j]) > 0 && (best == none || dict.nonbasic[j] < dict.nonbasic[best])) best = j;
  }
  return best;
}

// Bland: among the rows that limit the entering variable most, the one whose
// basic variable index is smallest.
std::size_t leaving_row(const Dictionary& dict, std::size_t column) {
  std::size_t best = none;
  Rational best_ratio;
  for (std::size_t i = 0; i < dict.basic.size(); ++i) {
    if (sgn(dict.coef[i][column]) >= 0) continue;
    Rational ratio = dict.constant[i] / -dict.coef[i][column];
    if (best == none || ratio < best_ratio || (ratio == best_ratio && dict.basic[i] < dict.basic[best])) {
      best = i;
      best_ratio = std::move(ratio);
    }
  }
  return best;
}

void substitute(std::vector<Rational>& coef, Rational& constant, const std::vector<Rational>& pivot_coef,
                const Rational& pivot_constant, std::size_t column) {
  const Rational factor = coef[column];
  if (sgn(factor) == 0) return;
  constant += factor * pivot_constant;
  for (std::size_t j = 0; j < coef.size(); ++j) {
    if (j == column) {
      coef[j] = factor * pivot_coef[j];
    } else {
      coef[j] += factor * pivot_coef[j];
    }
  }
}

void pivot(Dictionary& dict, std::size_t row, std::size_t column) {
  std::vector<Rational>& r = dict.coef[row];
  const Rational inverse = 1 / r[column];
  // Solve the pivot row for the entering variable.
  dict.constant[row] = -dict.constant[row] * inverse;
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (j == column) {
      r[j] = inverse;
    } else {
      r[j] = -r[j] * inverse;
    }
  }
  for (std::size_t i = 0; i < dict.basic.size(); ++i) {
    if (i != row) substitute(dict.coef[i], dict.constant[i], r, dict.constant[row], column);
  }
  substitute(dict.objective_coef, dict.objective, r, dict.constant[row], column);
  std::swap(dict.basic[row], dict.nonbasic[column]);
}

}  // namespace

MaxSlack max_slack(const std::vector<LpRow>& rows, int dimension) {
  Rational shift = 0;
  for (const LpRow& row : rows) {
    if (row.b < -shift) shift = -row.b;
  }
  Dictionary dict = initial_dictionary(rows, dimension, shift);
  for (std::size_t column; (column = entering_column(dict)) != none;) {
    pivot(dict, leaving_row(dict, column), column);  // bounded: a row always limits
  }
  MaxSlack result;
  result.slack = dict.objective - shift;
  const auto d = static_cast<std::size_t>(dimension);
  std::vector<Rational> value(2 * d + 1 + dict.basic.size(), Rational(0));
  for (std::size_t i = 0; i < dict.basic.size(); ++i) value[dict.basic[i]] = dict.constant[i];
  for (std::size_t k = 0; k < d; ++k) result.point.push_back(value[k] - value[d + k]);
  const std::size_t first_slack = 2 * d + 1;
  for (std::size_t j = 0; j < dict.nonbasic.size(); ++j) {
    const std::size_t var = dict.nonbasic[j];
    if (var >= first_slack && var - first_slack < rows.size() && sgn(dict.objective_coef[j]) < 0) {
      result.tight.push_back(var - first_slack);
    }
  }
  return result;
}

}  // namespace cvms::detail
