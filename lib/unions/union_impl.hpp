// SPDX-License-Identifier: MIT
// What a ConvexUnion shares between its copies: the pieces, and their box
// hierarchy, built by the first query that needs it. std::call_once makes
// the build happen once even when copies are queried from several threads,
// and publishes it to all of them; after that the hierarchy is only read.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "box_hierarchy.hpp"
#include "cvms/convex_union.hpp"

namespace cvms {

struct ConvexUnion::Impl {
  std::vector<ConvexPolyhedron> pieces;

  /// The hierarchy over the pieces' boxes.
  [[nodiscard]] const unions::BoxHierarchy& hierarchy() const;

 private:
  mutable std::once_flag built_;
  mutable std::unique_ptr<const unions::BoxHierarchy> hierarchy_;
};

}  // namespace cvms
