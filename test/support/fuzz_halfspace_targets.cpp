// SPDX-License-Identifier: MIT
// The half-space fuzz targets (fuzz_targets.hpp): the cdd and plain readers
// with their exact round trips, and intersect_halfspaces, to_halfspaces and
// pontryagin_difference on small decoded systems, each against the
// brute-force oracle of support/halfspace_oracle.hpp (triple enumeration in
// plain rationals, nothing of lib/halfspaces/).
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/set_sum.hpp"
#include "support/fuzz_bytes.hpp"
#include "support/fuzz_targets.hpp"
#include "support/halfspace_oracle.hpp"
#include "support/set_oracle.hpp"

namespace cvms::fuzz {
namespace {

bool canonical_rows(const std::vector<HalfspaceRow>& rows) {
  return std::all_of(rows.begin(), rows.end(), [](const HalfspaceRow& r) {
    return is_canonical(r.normal.x) && is_canonical(r.normal.y) && is_canonical(r.normal.z) &&
           is_canonical(r.offset);
  });
}

// Small enough for the O(m^4) oracle to stay well inside libFuzzer's
// timeout: a few dozen rows of numbers up to 256 bits.
bool small_system(const HalfspaceSystem& s) {
  if (2 * s.equalities.size() + s.inequalities.size() > 24) return false;
  const auto short_number = [](const Rational& r) {
    return mpz_sizeinbase(r.get_num_mpz_t(), 2) <= 256 && mpz_sizeinbase(r.get_den_mpz_t(), 2) <= 256;
  };
  return std::all_of(s.equalities.begin(), s.equalities.end(),
                     [&](const HalfspaceRow& r) { return short_number(r.offset); }) &&
         std::all_of(s.inequalities.begin(), s.inequalities.end(), [&](const HalfspaceRow& r) {
           return short_number(r.offset) && short_number(r.normal.x) && short_number(r.normal.y) &&
                  short_number(r.normal.z);
         });
}

// An unbounded answer: d nonzero, a·d <= 0 for every inequality and == 0
// for every equality, no set, and from_halfspaces refusing the system.
void check_unbounded(const HalfspaceSystem& system, const HalfspaceIntersection& got,
                     const std::string& who) {
  const Vec3& d = *got.unbounded_direction;
  if (d == Vec3{0, 0, 0}) finding(who + ": unbounded along the zero vector");
  for (const HalfspaceRow& r : system.inequalities)
    if (dot(r.normal, d) > 0) finding(who + ": the unbounded direction leaves an inequality");
  for (const HalfspaceRow& r : system.equalities)
    if (dot(r.normal, d) != 0) finding(who + ": the unbounded direction leaves an equality");
  if (!got.set.empty()) finding(who + ": an unbounded answer with a set");
  try {
    (void)from_halfspaces(system);
  } catch (const Error&) {
    return;
  }
  finding(who + ": from_halfspaces accepted an unbounded system");
}

// to_halfspaces gives primitive integer rows whose intersection is the set again.
void check_round_trip(const ConvexSet& set, const test::SetShape& shape, const std::string& who) {
  const HalfspaceSystem rows = to_halfspaces(set);
  for (const std::vector<HalfspaceRow>* part : {&rows.equalities, &rows.inequalities})
    for (const HalfspaceRow& r : *part)
      if (primitive_row(r) != r) finding(who + ": to_halfspaces gave a row that is not primitive");
  if (test::describe_set(from_halfspaces(rows)) != shape)
    finding(who + ": from_halfspaces(to_halfspaces(s)) != s");
}

// A ⊖ B against the brute-force intersection of A − b over B's vertices,
// and (A ⊖ B) ⊕ B ⊆ A.
void check_difference(const ConvexSet& a, const ConvexSet& b, const std::string& who) {
  const ConvexSet d = pontryagin_difference(a, b);
  const std::string bad = test::check_set_invariants(d);
  if (!bad.empty()) finding(who + ": pontryagin_difference: " + bad);
  const test::SetShape expected = test::brute_force_difference(a, b);
  const test::SetShape actual = test::describe_set(d);
  if (actual != expected)
    finding(who + ": pontryagin_difference (dimensions " + std::to_string(a.dimension()) + ", " +
            std::to_string(b.dimension()) +
            ") differs from the brute force:" + test::difference(expected, actual));
  if (!d.empty() && !test::contained(minkowski_sum(d, b), a)) finding(who + ": (A - B) + B is not inside A");
}

// The intersection against the brute force, then the round trip and, when
// `b` is given, the difference by it.
void check_intersection(const HalfspaceSystem& system, const std::string& who, const ConvexSet* b) {
  const HalfspaceIntersection got = intersect_halfspaces(system);
  if (got.unbounded_direction) {
    check_unbounded(system, got, who);
    return;
  }
  const std::string bad = test::check_set_invariants(got.set);
  if (!bad.empty()) finding(who + ": " + bad);
  const test::SetShape expected = test::brute_force_intersection(test::as_inequalities(system));
  const test::SetShape actual = test::describe_set(got.set);
  if (actual != expected)
    finding(who +
            ": intersect_halfspaces differs from the brute force:" + test::difference(expected, actual));
  check_round_trip(got.set, actual, who);
  if (b != nullptr && !got.set.empty()) check_difference(got.set, *b, who);
}

std::string text_of(ByteStream& in) {
  const std::span<const std::uint8_t> rest = in.rest();
  return {reinterpret_cast<const char*>(rest.data()), rest.size()};
}

void cdd_points_case(const std::string& text) {
  const ReadLimits limits = fuzz_limits();
  std::vector<Vec3> points;
  try {
    std::istringstream in(text);
    points = read_cdd_points(in, "<fuzz>", limits);
  } catch (const Error&) {
    return;
  }
  if (points.size() > limits.max_vertices) finding("read_cdd_points: more points than max_vertices");
  for (const Vec3& p : points)
    if (!is_canonical(p.x) || !is_canonical(p.y) || !is_canonical(p.z))
      finding("read_cdd_points: non-canonical rational coordinate");
  if (points.size() > 64) return;
  // The hull's vertices written and read back are the same points.
  const ConvexSet hull = convex_hull_set(points);
  std::ostringstream out;
  write_cdd_points(out, hull);
  std::istringstream back(out.str());
  std::vector<Vec3> again;
  try {
    again = read_cdd_points(back, "<round trip>", ReadLimits{});
  } catch (const Error& e) {
    finding(std::string("read_cdd_points refused write_cdd_points' output: ") + e.what());
  }
  std::vector<Vec3> vertices = hull.vertices();
  std::sort(vertices.begin(), vertices.end());
  std::sort(again.begin(), again.end());
  if (again != vertices) finding("write_cdd_points then read_cdd_points changed the vertices");
}

// Rows decoded one operation at a time (see halfspaces_target in the header).
std::vector<HalfspaceRow> decode_rows(ByteStream& in, bool grid) {
  std::vector<HalfspaceRow> rows;
  const std::size_t count = in.next() % 20;
  for (std::size_t i = 0; i < count && !in.empty(); ++i) {
    const std::uint8_t op = in.next();
    const bool have_row = !rows.empty();
    const HalfspaceRow& earlier = have_row ? rows[in.next() % rows.size()] : HalfspaceRow{};
    switch (have_row ? op % 8 : 0) {
      case 4: {  // an earlier row scaled by a positive factor: the same half-space
        const Rational k = fraction(1 + in.next() % 4, 1 + in.next() % 3);
        rows.push_back({k * earlier.normal, k * earlier.offset});
        break;
      }
      case 5: {  // its opposite, through the same plane (an implied equality) or near it
        const Rational slack = fraction(static_cast<long>(in.next() % 5) - 2, 4);
        rows.push_back({-earlier.normal, slack - earlier.offset});
        break;
      }
      case 6:  // a zero row 0 <= b
        rows.push_back({Vec3{0, 0, 0}, decode_coordinate(in.next())});
        break;
      case 7: {  // moved by a tiny step: nearly redundant, nearly degenerate
        const long k = static_cast<long>(in.next() % 7) - 3;
        rows.push_back({earlier.normal, earlier.offset + Rational(k) * power_of_two(-20 - in.next() % 60)});
        break;
      }
      default:
        rows.push_back({decode_point(in, grid), decode_coordinate(in.next())});
        break;
    }
  }
  return rows;
}

// The box |x_i| <= r, r from one byte (1 to 4): most systems bounded.
void add_box(std::vector<HalfspaceRow>& rows, ByteStream& in) {
  const Rational r(1 + in.next() % 4);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 e{0, 0, 0};
    e[axis] = 1;
    rows.push_back({e, r});
    rows.push_back({-e, r});
  }
}

// The rows of a file of the plane: each with a zero z coefficient, except
// the equality z == 0 that the reader adds.
bool in_the_plane(const HalfspaceSystem& system) {
  const HalfspaceRow z_is_zero{Vec3{0, 0, 1}, Rational(0)};
  bool has_z_is_zero = false;
  for (const HalfspaceRow& row : system.equalities) {
    if (row == z_is_zero)
      has_z_is_zero = true;
    else if (row.normal.z != 0)
      return false;
  }
  for (const HalfspaceRow& row : system.inequalities)
    if (row.normal.z != 0) return false;
  return has_z_is_zero;
}

// Every row holds on the whole plane z = 0 (0 <= b with b >= 0, 0 == 0).
bool whole_plane(const HalfspaceSystem& system) {
  const auto flat = [](const HalfspaceRow& r) { return sgn(r.normal.x) == 0 && sgn(r.normal.y) == 0; };
  for (const HalfspaceRow& r : system.equalities)
    if (!flat(r) || sgn(r.offset) != 0) return false;
  for (const HalfspaceRow& r : system.inequalities)
    if (!flat(r) || sgn(r.offset) < 0) return false;
  return true;
}

// A file of the plane is written as its rows restricted to the plane, made
// primitive, without repeats and without the rows that hold on the whole
// plane (halfspace_io.hpp), so the rows read back need not be the rows
// given: the written text must read back, and be written again unchanged.
// Only a system of rows that all hold on the whole plane writes no row, and
// a file of no row is refused.
void check_plane_round_trip(const std::string& text, const HalfspaceSystem& system, HalfspaceFormat format,
                            const char* who) {
  std::istringstream back(text);
  HalfspaceFile again;
  try {
    again = read_halfspaces_of_any_dimension(back, format, "<round trip>", ReadLimits{});
  } catch (const Error& e) {
    if (!whole_plane(system)) finding(std::string(who) + ": refused write_halfspaces' output: " + e.what());
    return;
  }
  std::ostringstream out;
  write_halfspaces(out, again.system, format, 2);
  if (again.dimension != 2 || out.str() != text)
    finding(std::string(who) + ": rows of the plane read back were written differently");
}

}  // namespace

void read_halfspaces_target(std::span<const std::uint8_t> data) {
  ByteStream in(data);
  const std::uint8_t mode = in.next();
  const std::string text = text_of(in);
  if (mode % 3 == 2) {
    cdd_points_case(text);
    return;
  }
  const HalfspaceFormat format = mode % 3 == 0 ? HalfspaceFormat::cdd : HalfspaceFormat::plain;
  const char* who = format == HalfspaceFormat::cdd ? "read_halfspaces (cdd)" : "read_halfspaces (plain)";
  const ReadLimits limits = fuzz_limits();
  HalfspaceFile file;
  try {
    std::istringstream stream(text);
    file = read_halfspaces_of_any_dimension(stream, format, "<fuzz>", limits);
  } catch (const Error&) {
    return;
  }
  const HalfspaceSystem& system = file.system;
  if (system.equalities.size() + system.inequalities.size() >
      limits.max_faces + (file.dimension == 2 ? 1 : 0))
    finding(std::string(who) + ": more rows than max_faces");
  if (!canonical_rows(system.equalities) || !canonical_rows(system.inequalities))
    finding(std::string(who) + ": non-canonical rational entry");
  // A plain file of space has inequalities only; a file of the plane (either
  // form) is its rows with a zero z coefficient plus the equality z == 0.
  if (file.dimension == 3 && format == HalfspaceFormat::plain && !system.equalities.empty())
    finding(std::string(who) + ": equalities from the plain form");
  if (file.dimension == 2 && !in_the_plane(system))
    finding(std::string(who) + ": a file of the plane gave rows outside the plane z = 0");
  std::ostringstream out;
  write_halfspaces(out, system, format, file.dimension);
  if (file.dimension == 2) {
    check_plane_round_trip(out.str(), system, format, who);
  } else {
    std::istringstream back(out.str());
    HalfspaceFile again;
    try {
      again = read_halfspaces_of_any_dimension(back, format, "<round trip>", ReadLimits{});
    } catch (const Error& e) {
      finding(std::string(who) + ": refused write_halfspaces' output: " + e.what());
    }
    if (again.dimension != 3 || again.system.equalities != system.equalities ||
        again.system.inequalities != system.inequalities)
      finding(std::string(who) + ": write_halfspaces then read_halfspaces changed the rows");
  }
  if (small_system(system)) check_intersection(system, who, nullptr);
}

void halfspaces_target(std::span<const std::uint8_t> data) {
  ByteStream in(data);
  // mode: bit 0 a bounding box, bit 1 grid normals, bit 2 the first row an
  // equality, bit 3 every offset scaled by an extreme power of two.
  const std::uint8_t mode = in.next();
  std::vector<HalfspaceRow> rows;
  if ((mode & 1) != 0) add_box(rows, in);
  std::vector<HalfspaceRow> decoded = decode_rows(in, (mode & 2) != 0);
  rows.insert(rows.end(), decoded.begin(), decoded.end());
  if ((mode & 8) != 0) {
    const Rational s = power_of_two(static_cast<long>(static_cast<std::int8_t>(in.next())) * 8);
    for (HalfspaceRow& r : rows) r.offset *= s;
  }
  HalfspaceSystem system;
  if ((mode & 4) != 0 && !rows.empty()) {
    system.equalities.push_back(rows.front());
    rows.erase(rows.begin());
  }
  system.inequalities = std::move(rows);
  const ConvexSet b = decode_set(in);
  check_intersection(system, "halfspaces", &b);
}

}  // namespace cvms::fuzz
