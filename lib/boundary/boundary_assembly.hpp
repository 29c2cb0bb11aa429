// SPDX-License-Identifier: MIT
// The fragments of a union's boundary (boundary_fragments.hpp) joined into
// one closed mesh: the fragments of each oriented plane merged into maximal
// regions, corners that are not true corners of the boundary dropped, true
// corners that lie on another region's edge inserted there, each region
// triangulated without new vertices, and edges or points where parts of the
// set touch split so that every shell is a closed 2-manifold.
#pragma once

#include "boundary_fragments.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/solid.hpp"

namespace cvms::detail {

/// The solid bounded by the fragments.
/// \pre `fragments` is the boundary of a regularised union of convex
///   polyhedra, as union_boundary_fragments gives it (possibly with whole
///   fragments removed where they bound a part of the set the pieces do not
///   list, as the sum of a solid with a convex set does).
/// \throw Error(cancelled) if options.progress returns false.
Solid assemble_boundary(const BoundaryFragments& fragments, const Options& options);

}  // namespace cvms::detail
