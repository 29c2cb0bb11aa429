// SPDX-License-Identifier: MIT
// What one piece Q takes away from a facet f of another piece P on the
// plane h (outward normal n): the closed convex polygon C_Q of h whose
// points are not on the union's boundary because of Q, as cutting planes.
//
// A point x of f's relative interior, off a set of measure zero, is on the
// union's boundary iff no other piece covers the outer side of h near x.
// Q covers it iff x is in Q's interior (Q has vertices strictly on both
// sides of h, so Q ∩ h is a polygon of positive area), or Q has a facet on
// h facing the other way (Q lies on the outer side). A facet of Q on h
// facing the same way is the same stretch of boundary twice: the piece of
// smaller index keeps it. Otherwise Q meets h in an edge, a vertex or not
// at all, which covers nothing of positive area. So C_Q is Q ∩ h in the
// first three cases and empty otherwise.
//
// Q ∩ h as planes: within h it is the intersection of the half-spaces of
// Q's facets g that meet h in a segment (its edges lie on those), found
// from the sides of g's corners: corners strictly on both sides, or two
// corners on h without g lying in h. Three corners of Q on h with Q on one
// side mean that Q has a facet on h: Q's vertices are extreme, so no three
// of them lie on one edge, and three non-collinear points of Q on a
// supporting plane span a facet.
#pragma once

#include <cstdint>
#include <vector>

#include "cvms/sign.hpp"
#include "piece_geometry.hpp"
#include "plane_clip.hpp"
#include "section_walk.hpp"

namespace cvms::detail {

/// Fills `region` with the planes of C_Q for a facet on `plane` (the
/// facet's own half-space) of a piece with index p, Q having index q != p,
/// and returns true; false (region left empty) if C_Q is empty. The planes
/// come in the order of Q's facets. Tries a walk round the section first
/// (section_walk.hpp). When the walk gives up at a vertex on the plane that
/// is a corner of a facet of Q lying in the plane (neighbouring pieces often
/// share planes), C_Q is read off that facet: the facets across its edges;
/// when no neighbour of that vertex is strictly on each side, Q does not
/// cross the plane and touches it in no facet, so C_Q is empty; otherwise
/// Q crosses the plane through that vertex and the facets are found from it
/// outwards (section_through_vertex). Only a walk that gave up for another
/// reason leaves every vertex of Q to be tested.
/// `sides` and `section` are scratch space.
bool covering_region(const PieceGeometry& q_geometry, std::uint32_t q, bool q_before_p, const ClipPlane& plane,
                     std::vector<Sign>& sides, SectionScratch& section, std::vector<ClipPlane>& region);

/// True only if every point of the box lies strictly inside the plane's
/// half-space (dot(normal, x) < offset), decided by the filter alone (false
/// when it cannot prove it): the box's corner farthest along the normal has
/// the greatest dot(normal, x) of the box's points, and its coordinates are
/// doubles, so their approximation is exact. A corner with an infinite
/// coordinate is never proven inside. On a piece's box, one filtered test
/// stands for one test per vertex of the piece, with no exact value made.
bool box_strictly_inside(const unions::OutwardBox& box, const ClipPlane& plane);
/// The same for strictly outside (dot(normal, x) > offset), with the
/// corner nearest along the normal.
bool box_strictly_outside(const unions::OutwardBox& box, const ClipPlane& plane);

/// How a convex region of a facet's plane (given by half-spaces) meets the
/// facet: in zero area (some half-space has every corner on or outside its
/// plane), containing it (every corner inside or on every plane), or
/// otherwise in part.
enum class FacetOverlap { none, all, part };
FacetOverlap facet_overlap(const std::vector<ClipPlane>& region, const PieceGeometry& p_geometry,
                           std::uint32_t facet);

}  // namespace cvms::detail
