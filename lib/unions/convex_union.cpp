// SPDX-License-Identifier: MIT
// The union's value semantics and its pieces.
#include "cvms/convex_union.hpp"

#include <string>
#include <utility>

#include "cvms/error.hpp"
#include "union_impl.hpp"

namespace cvms {

const unions::BoxHierarchy& ConvexUnion::Impl::hierarchy() const {
  std::call_once(built_, [this] {
    std::vector<unions::OutwardBox> boxes;
    boxes.reserve(pieces.size());
    for (const ConvexPolyhedron& piece : pieces) boxes.push_back(unions::polyhedron_box(piece));
    hierarchy_ = std::make_unique<const unions::BoxHierarchy>(boxes);
  });
  return *hierarchy_;
}

ConvexUnion::ConvexUnion() = default;
ConvexUnion::~ConvexUnion() = default;
ConvexUnion::ConvexUnion(const ConvexUnion&) = default;
ConvexUnion::ConvexUnion(ConvexUnion&&) noexcept = default;
ConvexUnion& ConvexUnion::operator=(const ConvexUnion&) = default;
ConvexUnion& ConvexUnion::operator=(ConvexUnion&&) noexcept = default;

ConvexUnion::ConvexUnion(std::vector<ConvexPolyhedron> pieces) {
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (pieces[i].num_vertices() == 0) {
      throw Error(ErrorCategory::invalid_argument, "ConvexUnion: piece " + std::to_string(i) + " is empty");
    }
  }
  auto impl = std::make_shared<Impl>();
  impl->pieces = std::move(pieces);
  impl_ = std::move(impl);
}

std::span<const ConvexPolyhedron> ConvexUnion::pieces() const noexcept {
  if (!impl_) return {};
  return impl_->pieces;
}

std::size_t ConvexUnion::size() const noexcept { return impl_ ? impl_->pieces.size() : 0; }

}  // namespace cvms
