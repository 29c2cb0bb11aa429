// SPDX-License-Identifier: MIT
// Example: tightening the state constraints of a tube MPC controller.
//
// Tube MPC steers a nominal state z while the true state x = z + e stays
// in a tube around it; the error e lives in a set Z that absorbs the
// disturbance w ∈ W under the ancillary feedback: Z = W ⊕ A_K W ⊕ A_K² W ⊕ …
// (here its first three terms, A_K = [[1/2, 1/4], [0, 1/2]], the closed
// loop of the error). The nominal state must then satisfy the tightened
// constraints X ⊖ Z (the Pontryagin difference: z + Z ⊆ X for every z in
// it), which is what the controller's optimisation takes as rows.
//
// The program reads X as cdd rows of the plane (.ine, `m 3`), builds W as
// the box |w_i| <= 1/10, computes X ⊖ Z exactly, prints its rows as cdd's
// H-representation of the plane, and checks the defining property exactly:
// every vertex of X ⊖ Z plus every vertex of Z lies in X.
//
// Hand check: the support of Z is the sum of the supports of its terms, so
// in direction (1, 0) it is 1/10 + 3/40 + 1/20 = 9/40, in (0, 1) it is
// 1/10 + 1/20 + 1/40 = 7/40 and in (1, 1) it is 1/5 + 1/8 + 3/40 = 2/5; X
// is tightened to |x1| <= 191/40, |x2| <= 73/40 and x1 + x2 <= 28/5.
#include <cvms/convex_hull.hpp>
#include <cvms/error.hpp>
#include <cvms/halfspace_io.hpp>
#include <cvms/halfspaces.hpp>
#include <cvms/set_sum.hpp>
#include <iostream>
#include <vector>

namespace {

using cvms::Rational;
using cvms::Vec3;

// A_K x in the plane z = 0.
Vec3 closed_loop(const Vec3& x) { return {x.x / 2 + x.y / 4, x.y / 2, Rational(0)}; }

// Z = W ⊕ A_K W ⊕ A_K² W for the box W = [-1/10, 1/10]².
cvms::ConvexSet error_set() {
  const Rational d(1, 10);
  std::vector<Vec3> corners = {{-d, -d, 0}, {d, -d, 0}, {d, d, 0}, {-d, d, 0}};
  std::vector<cvms::ConvexSet> terms;
  for (int k = 0; k < 3; ++k) {
    terms.push_back(cvms::convex_hull_set(corners));
    for (Vec3& c : corners) c = closed_loop(c);
  }
  return cvms::minkowski_sum(terms);
}

// Every row a·x <= b of the system holds at p, exactly.
bool satisfies(const cvms::HalfspaceSystem& system, const Vec3& p) {
  for (const cvms::HalfspaceRow& row : system.inequalities)
    if (dot(row.normal, p) > row.offset) return false;
  for (const cvms::HalfspaceRow& row : system.equalities)
    if (dot(row.normal, p) != row.offset) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: tube_mpc STATE_CONSTRAINTS.ine\n";
    return 2;
  }
  try {
    const cvms::HalfspaceFile x_rows = cvms::read_halfspace_file_of_any_dimension(argv[1]);
    const cvms::ConvexSet x = cvms::from_halfspaces(x_rows.system);
    const cvms::ConvexSet z = error_set();
    const cvms::ConvexSet tightened = cvms::pontryagin_difference(x, z);
    std::cout << "error set Z: " << z.num_vertices() << " vertices\n";
    cvms::write_halfspaces(std::cout, cvms::to_halfspaces(tightened), cvms::HalfspaceFormat::cdd, x_rows.dimension);
    bool inside = true;
    for (const Vec3& v : tightened.vertices())
      for (const Vec3& e : z.vertices()) inside = inside && satisfies(x_rows.system, v + e);
    std::cout << "tightened + Z inside X: " << (inside ? "yes" : "no") << "\n";
    return inside ? 0 : 1;
  } catch (const cvms::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
