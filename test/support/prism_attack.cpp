// SPDX-License-Identifier: MIT
// The prism attack pair (see prism_attack.hpp).
#include "support/prism_attack.hpp"

#include "cvms/shapes.hpp"

namespace cvms::test {

PrismPair prism_attack(int n) {
  Mat3 quarter_turn_x;  // (x, y, z) -> (x, -z, y), exact
  quarter_turn_x.m[0][0] = 1;
  quarter_turn_x.m[1][2] = -1;
  quarter_turn_x.m[2][1] = 1;
  return {shapes::prism(n, 2), shapes::prism(n, 3).transformed(quarter_turn_x, {})};
}

}  // namespace cvms::test
