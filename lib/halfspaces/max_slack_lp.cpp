// SPDX-License-Identifier: MIT
// The max-slack LP of max_slack_lp.hpp by the simplex method in dictionary
// form (Chvátal, "Linear Programming", ch. 2-3) in exact arithmetic,
// revised so that a pivot costs O(d) integer products per row instead of
// 2d + 1 rational updates.
//
// Shape: the free unknowns are split, u = p − q with p, q >= 0, and the
// slack is shifted, t = t' − M with M = max(0, −min b_i), so that every
// right-hand side b_i + M (and the bound 1 + M on t') is >= 0 and the origin
// is a feasible basis: one phase suffices. Bland's rule (smallest index
// enters and leaves) excludes cycling, so the method terminates; the
// objective t' is bounded by 1 + M, so it ends at an optimum. The indices
// Bland's rule compares are those of a pseudo-random order of the rows
// (pseudo_random_order): in the order given, rows sorted by an adversary
// make it take a pivot per row (the tangent planes of a sphere, farthest
// first: over a thousand pivots for 900 rows, about ten when shuffled).
//
// Revision: the dictionary of a basis is unique, so any way of computing
// its entries takes the same pivots. The 2d + 1 structural variables
// (p, q, t') and the objective keep full rows; the row of a basic slack
// w_i = (b_i + M) − a_i·(p − q) − t' is never stored but read off its
// definition with the structural rows substituted: its entry in column e is
// a_i·(D_q − D_p) − D_t and its constant (b_i + M) + a_i·(C_q − C_p) − C_t,
// D_s and C_s the column-e entry and the constant of x_s in the dictionary
// (a unit or zero column for a nonbasic x_s). The ratio test needs only
// those two numbers per row and compares the ratios constant / −entry,
// which a positive factor per row does not change: each row is scaled to
// integers once (L_i > 0), the vectors D_q − D_p, C_q − C_p are put over
// one denominator each per pivot, and the ratios are compared by cross
// multiplication, so the scan builds no rational.
#include "max_slack_lp.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

namespace cvms::detail {

namespace {

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

// x_basic = constant + sum_j coef[j] * (the variable of column j).
struct Row {
  Rational constant;
  std::vector<Rational> coef;
};

// Constraint i scaled by L_i > 0 to integers: L_i w_i = b − a·(p − q) − t t'.
struct IntegerConstraint {
  std::vector<mpz_class> a;
  mpz_class t, b;
};

// Variables: p_0..p_{d-1}, q_0..q_{d-1}, t' (structural), then one slack
// per constraint (the last constraint is t' <= 1 + M, with a == 0).
class Simplex {
 public:
  // Constraint i is rows[order[i]].
  Simplex(const std::vector<LpRow>& rows, std::vector<std::size_t> order, int d, const Rational& shift)
      : d_(static_cast<std::size_t>(d)), columns_(2 * d_ + 1), rows_(rows), order_(std::move(order)), shift_(shift) {
    for (std::size_t j = 0; j < columns_; ++j) nonbasic_.push_back(j);
    column_of_.assign(columns_ + rows.size() + 1, none);
    for (std::size_t j = 0; j < columns_; ++j) column_of_[j] = j;
    structural_.resize(columns_);
    objective_.coef.assign(columns_, Rational(0));
    objective_.coef[columns_ - 1] = 1;
    for (std::size_t i = 0; i <= rows.size(); ++i) integer_.push_back(integer_constraint(i));
  }

  void run() {
    for (std::size_t column; (column = entering_column()) != none; ++pivots_) pivot(leaving_variable(column), column);
  }

  MaxSlack result() const {
    MaxSlack result;
    result.slack = objective_.constant - shift_;
    for (std::size_t k = 0; k < d_; ++k) result.point.push_back(value(k) - value(d_ + k));
    for (std::size_t j = 0; j < columns_; ++j) {
      const std::size_t var = nonbasic_[j];
      if (var >= columns_ && var - columns_ < rows_.size() && sgn(objective_.coef[j]) < 0)
        result.tight.push_back(order_[var - columns_]);
    }
    std::sort(result.tight.begin(), result.tight.end());
    result.pivots = pivots_;
    return result;
  }

 private:
  // The constraint's a_k (zero for the bound on t') and b + M.
  const Rational* a(std::size_t i, std::size_t k) const {
    return i < rows_.size() ? &rows_[order_[i]].a[k] : nullptr;
  }
  Rational right_side(std::size_t i) const { return (i < rows_.size() ? rows_[order_[i]].b : Rational(1)) + shift_; }

  // The constraint times L_i, the lcm of its denominators.
  IntegerConstraint integer_constraint(std::size_t i) const {
    const Rational b = right_side(i);
    IntegerConstraint c{{}, b.get_den(), 0};
    for (std::size_t k = 0; k < d_; ++k)
      if (const Rational* ak = a(i, k); ak && mpz_cmp_ui(ak->get_den_mpz_t(), 1) != 0)
        mpz_lcm(c.t.get_mpz_t(), c.t.get_mpz_t(), ak->get_den_mpz_t());
    times(b, c.t, c.b);
    c.a.resize(d_);
    for (std::size_t k = 0; k < d_; ++k)
      if (const Rational* ak = a(i, k)) times(*ak, c.t, c.a[k]);
    return c;
  }

  // out = q · l, an integer as q's denominator d divides l: the numerator
  // times the exact quotient l / d, or the numerator itself when d == l
  // (integer rows: no product, division or gcd).
  static void times(const Rational& q, const mpz_class& l, mpz_class& out) {
    if (mpz_cmp(l.get_mpz_t(), q.get_den_mpz_t()) == 0) {
      out = q.get_num();
      return;
    }
    mpz_divexact(out.get_mpz_t(), l.get_mpz_t(), q.get_den_mpz_t());
    out *= q.get_num();
  }

  // The column-j entry (or, for j == none, the constant) of structural x_s.
  Rational structural_entry(std::size_t s, std::size_t j) const {
    if (structural_[s]) return j == none ? structural_[s]->constant : structural_[s]->coef[j];
    return Rational(j != none && column_of_[s] == j ? 1 : 0);
  }

  // a_i·(x_q − x_p) − x_t' for the entries of column j (or the constants):
  // the vector D_q − D_p and the scalar −D_t'.
  void slack_terms(std::size_t j, std::vector<Rational>& u, Rational& u0) const {
    u.resize(d_);
    for (std::size_t k = 0; k < d_; ++k) u[k] = structural_entry(d_ + k, j) - structural_entry(k, j);
    u0 = -structural_entry(2 * d_, j);
  }

  // The full dictionary row of the basic variable var.
  Row row_of(std::size_t var) const {
    if (var < columns_) return *structural_[var];
    const std::size_t i = var - columns_;
    std::vector<Rational> u;
    Rational u0;
    Row r;
    for (std::size_t j = 0; j <= columns_; ++j) {
      const std::size_t column = j == columns_ ? none : j;
      slack_terms(column, u, u0);
      Rational v = column == none ? right_side(i) + u0 : u0;
      for (std::size_t k = 0; k < d_; ++k)
        if (const Rational* ak = a(i, k)) v += *ak * u[k];
      if (column == none)
        r.constant = std::move(v);
      else
        r.coef.push_back(std::move(v));
    }
    return r;
  }

  Rational value(std::size_t var) const { return structural_[var] ? structural_[var]->constant : Rational(0); }

  // Bland: the entering column with a positive objective coefficient whose
  // variable index is smallest; none at an optimum.
  std::size_t entering_column() const {
    std::size_t best = none;
    for (std::size_t j = 0; j < columns_; ++j)
      if (sgn(objective_.coef[j]) > 0 && (best == none || nonbasic_[j] < nonbasic_[best])) best = j;
    return best;
  }

  // Bland: among the basic variables that limit column j's most, the one
  // with the smallest index.
  std::size_t leaving_variable(std::size_t column) const {
    std::size_t best = none;
    Rational best_ratio;
    auto consider = [&](std::size_t var, Rational ratio) {
      if (best == none || ratio < best_ratio || (ratio == best_ratio && var < best)) {
        best = var;
        best_ratio = std::move(ratio);
      }
    };
    for (std::size_t s = 0; s < columns_; ++s)
      if (structural_[s] && sgn(structural_[s]->coef[column]) < 0)
        consider(s, structural_[s]->constant / -structural_[s]->coef[column]);
    if (const std::optional<std::pair<std::size_t, Rational>> slack = limiting_slack(column))
      consider(slack->first, slack->second);
    return best;
  }

  // The basic slack that limits column j most (smallest index on ties),
  // with its ratio.
  std::optional<std::pair<std::size_t, Rational>> limiting_slack(std::size_t column) const {
    const Over entry = over_one_denominator(column), constant = over_one_denominator(none);
    std::size_t best = none;
    mpz_class n, k, best_n, best_k, lhs, rhs;
    for (std::size_t i = 0; i < integer_.size(); ++i) {
      if (column_of_[columns_ + i] != none) continue;  // nonbasic
      const IntegerConstraint& c = integer_[i];
      // L_i * entry * entry.den and L_i * constant * constant.den.
      n = c.t * entry.scalar;
      k = c.b * constant.den + c.t * constant.scalar;
      for (std::size_t m = 0; m < d_; ++m) {
        mpz_addmul(n.get_mpz_t(), c.a[m].get_mpz_t(), entry.vector[m].get_mpz_t());
        mpz_addmul(k.get_mpz_t(), c.a[m].get_mpz_t(), constant.vector[m].get_mpz_t());
      }
      if (sgn(n) >= 0) continue;
      // k / −n < best_k / −best_n, both denominators positive.
      if (best != none) {
        lhs = k * best_n;
        rhs = best_k * n;
        if (lhs <= rhs) continue;  // not smaller (the earlier index wins ties)
      }
      best = i;
      best_n = n;
      best_k = k;
    }
    if (best == none) return std::nullopt;
    Rational ratio(mpz_class(best_k * entry.den), mpz_class(-best_n * constant.den));
    ratio.canonicalize();
    return std::pair{columns_ + best, std::move(ratio)};
  }

  // The slack terms of column j (or of the constants) over one positive
  // denominator: vector == den * (D_q − D_p), scalar == den * (−D_t').
  struct Over {
    std::vector<mpz_class> vector;
    mpz_class scalar, den;
  };
  Over over_one_denominator(std::size_t j) const {
    std::vector<Rational> u;
    Rational u0;
    slack_terms(j, u, u0);
    Over o{{}, 0, 1};
    mpz_lcm(o.den.get_mpz_t(), o.den.get_mpz_t(), u0.get_den_mpz_t());
    for (const Rational& v : u) mpz_lcm(o.den.get_mpz_t(), o.den.get_mpz_t(), v.get_den_mpz_t());
    for (const Rational& v : u) o.vector.push_back(mpz_class(v * o.den));
    o.scalar = mpz_class(u0 * o.den);
    return o;
  }

  static void substitute(Row& row, const Row& pivot_row, std::size_t column) {
    const Rational factor = row.coef[column];
    if (sgn(factor) == 0) return;
    row.constant += factor * pivot_row.constant;
    for (std::size_t j = 0; j < row.coef.size(); ++j) {
      if (j == column) {
        row.coef[j] = factor * pivot_row.coef[j];
      } else {
        row.coef[j] += factor * pivot_row.coef[j];
      }
    }
  }

  void pivot(std::size_t leaving, std::size_t column) {
    // Solve the leaving variable's row for the entering variable, whose
    // column then stands for the leaving one.
    Row r = row_of(leaving);
    const Rational inverse = 1 / r.coef[column];
    r.constant = -r.constant * inverse;
    for (std::size_t j = 0; j < columns_; ++j) r.coef[j] = j == column ? inverse : -r.coef[j] * inverse;
    const std::size_t entering = nonbasic_[column];
    if (leaving < columns_) structural_[leaving].reset();
    for (std::optional<Row>& s : structural_)
      if (s) substitute(*s, r, column);
    substitute(objective_, r, column);
    if (entering < columns_) structural_[entering] = std::move(r);
    nonbasic_[column] = leaving;
    column_of_[leaving] = column;
    column_of_[entering] = none;
  }

  std::size_t d_, columns_;
  const std::vector<LpRow>& rows_;
  std::vector<std::size_t> order_;  // constraint i is rows_[order_[i]]
  Rational shift_;
  std::size_t pivots_ = 0;
  std::vector<std::size_t> nonbasic_;            // variable of each column
  std::vector<std::size_t> column_of_;           // column of each variable, none if basic
  std::vector<std::optional<Row>> structural_;   // rows of the basic structural variables
  Row objective_;
  std::vector<IntegerConstraint> integer_;
};

// splitmix64 (Steele, Lea, Flood: "Fast splittable pseudorandom number
// generators"): a fixed, portable generator, so the order is the same on
// every platform (std::shuffle's is not).
std::uint64_t next_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void mix(std::uint64_t& hash, const mpz_class& n) {
  hash = (hash ^ mpz_get_ui(n.get_mpz_t()) ^ static_cast<std::uint64_t>(mpz_sgn(n.get_mpz_t()) + 1)) *
         0x100000001b3ULL;
}

// A Fisher-Yates permutation of the rows, seeded from their numbers (the
// low bits of each numerator and denominator, in row order): deterministic,
// and an input cannot be arranged for it without searching for a seed.
std::vector<std::size_t> pseudo_random_order(const std::vector<LpRow>& rows) {
  std::uint64_t state = 0xcbf29ce484222325ULL;
  for (const LpRow& row : rows) {
    for (const Rational& v : row.a) {
      mix(state, v.get_num());
      mix(state, v.get_den());
    }
    mix(state, row.b.get_num());
    mix(state, row.b.get_den());
  }
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[next_random(state) % i]);
  return order;
}

}  // namespace

MaxSlack max_slack(const std::vector<LpRow>& rows, int dimension) {
  Rational shift = 0;
  for (const LpRow& row : rows) {
    if (row.b < -shift) shift = -row.b;
  }
  Simplex simplex(rows, pseudo_random_order(rows), dimension, shift);
  simplex.run();
  return simplex.result();
}

}  // namespace cvms::detail
