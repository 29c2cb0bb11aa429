// SPDX-License-Identifier: MIT
// Directions ordered by angle in an oriented plane, counterclockwise from a
// reference direction r over [0, 2pi), with no angle computed (DESIGN.md:
// compare, don't construct). A nonzero v lies in the half-turn [0, pi) iff
// cross(r, v) > 0, or cross(r, v) = 0 and <r, v> > 0 (v along r); else in
// [pi, 2pi). Directions in different half-turns are ordered by their
// half-turn; within one half-turn, b is counterclockwise of a iff
// cross(a, b) > 0, and cross(a, b) = 0 means the same direction, since
// opposite directions lie in different half-turns.
//
// "cross" is the orientation of the plane: sign_cross2 in the plane (with r
// the x axis, the signs of cross(r, v) and <r, v> are those of v.y and v.x),
// det[n, a, b] on a plane of R^3 with normal n. The caller supplies the
// signs, so that each evaluates them its cheapest exact way; a sign passed as
// a callable is evaluated only when the order depends on it.
#pragma once

#include "cvms/sign.hpp"

namespace cvms::detail {

/// 0 if v (nonzero) lies in [0, pi) from r, 1 if in [pi, 2pi), from the sign
/// of cross(r, v) and, through dot(), the sign of <r, v> (called only when
/// cross(r, v) is zero).
template <class DotSign>
int half_turn(Sign cross_rv, DotSign&& dot) {
  return (cross_rv == Sign::positive || (cross_rv == Sign::zero && dot() == Sign::positive)) ? 0 : 1;
}

/// The sign of angle(a) - angle(b), angles in [0, 2pi) from r, for nonzero
/// a and b in the half-turns ha and hb (half_turn); cross() gives the sign of
/// cross(a, b) and is called only when ha == hb.
template <class CrossSign>
Sign compare_angle(int ha, int hb, CrossSign&& cross) {
  if (ha != hb) return ha < hb ? Sign::negative : Sign::positive;
  return -cross();
}

}  // namespace cvms::detail
