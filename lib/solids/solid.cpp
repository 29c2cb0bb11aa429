// SPDX-License-Identifier: MIT
// The solid's value semantics and accessors. Its validation lives in the
// files beside this one.
#include "cvms/solid.hpp"

#include <memory>
#include <utility>

#include "solid_access.hpp"
#include "solid_impl.hpp"

namespace cvms {

Solid::Solid() = default;
Solid::~Solid() = default;
Solid::Solid(const Solid&) = default;
Solid::Solid(Solid&&) noexcept = default;
Solid& Solid::operator=(const Solid&) = default;
Solid& Solid::operator=(Solid&&) noexcept = default;

std::span<const Vec3> Solid::vertices() const noexcept {
  if (!impl_) return {};
  return impl_->vertices;
}

std::span<const std::array<std::uint32_t, 3>> Solid::triangles() const noexcept {
  if (!impl_) return {};
  return impl_->triangles;
}

std::span<const std::uint32_t> Solid::triangle_facets() const noexcept {
  if (!impl_) return {};
  return impl_->triangle_facets;
}

std::uint32_t Solid::num_facets() const noexcept {
  return impl_ ? static_cast<std::uint32_t>(impl_->facet_normals.size()) : 0;
}
const Vec3& Solid::facet_normal(std::uint32_t f) const { return impl_->facet_normals.at(f); }
const Rational& Solid::facet_offset(std::uint32_t f) const { return impl_->facet_offsets.at(f); }
std::uint32_t Solid::num_shells() const noexcept { return impl_ ? impl_->shells : 0; }
std::uint32_t Solid::num_cavities() const noexcept { return impl_ ? impl_->cavities : 0; }
std::uint32_t Solid::genus() const noexcept { return impl_ ? impl_->genus : 0; }
std::uint32_t Solid::num_reflex_edges() const noexcept { return impl_ ? impl_->reflex_edges : 0; }
bool Solid::is_convex() const noexcept { return impl_ && impl_->shells == 1 && impl_->reflex_edges == 0; }

const Rational& Solid::volume() const noexcept {
  static const Rational zero;
  return impl_ ? impl_->volume : zero;
}

// Placeholder until the derivation of facets, shells and volume lands: keeps
// the vertices and triangles, which is all a decomposition reads.
Solid SolidAccess::assume_valid(std::vector<Vec3> vertices,
                                std::vector<std::array<std::uint32_t, 3>> triangles) {
  auto impl = std::make_shared<Solid::Impl>();
  impl->vertices = std::move(vertices);
  impl->triangles = std::move(triangles);
  impl->shells = 1;
  Solid solid;
  solid.impl_ = std::move(impl);
  return solid;
}

}  // namespace cvms
