// SPDX-License-Identifier: MIT
// The data of a validated solid, shared by its copies (never copied itself:
// copies of a Solid share one Impl, so its lazily built hierarchy is built
// once for all of them).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/solid.hpp"
#include "cvms/vec.hpp"
#include "triangle_tree.hpp"

namespace cvms {

struct Solid::Impl {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // outward (inside on the back)
  std::vector<std::uint32_t> triangle_facets;           // facet of each triangle
  std::vector<Vec3> facet_normals;                      // primitive integer, outward
  std::vector<Rational> facet_offsets;
  std::uint32_t shells = 0;
  std::uint32_t cavities = 0;
  std::uint32_t genus = 0;
  std::uint32_t reflex_edges = 0;
  Rational volume;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  /// The hierarchy of the triangles: the one the validation built, or built
  /// now by the first caller (std::call_once: concurrent callers wait for
  /// that one construction).
  [[nodiscard]] const detail::TriangleTree& tree() const {
    std::call_once(tree_made_, [this] {
      if (!tree_) tree_ = std::make_unique<const detail::TriangleTree>(vertices, triangles);
    });
    return *tree_;
  }

 private:
  mutable std::once_flag tree_made_;
  mutable std::unique_ptr<const detail::TriangleTree> tree_;
};

}  // namespace cvms
