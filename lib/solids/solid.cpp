// SPDX-License-Identifier: MIT
// The solid's value semantics, accessors, conversions and point location.
// Its validation is solid_from_soup.cpp.
#include "cvms/solid.hpp"

#include <memory>
#include <utility>

#include "cvms/error.hpp"
#include "ray_parity.hpp"
#include "solid_access.hpp"
#include "solid_impl.hpp"
#include "solid_properties.hpp"
#include "triangle_intersection.hpp"
#include "triangle_tree.hpp"

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

Solid SolidAccess::assume_valid(std::vector<Vec3> vertices,
                                std::vector<std::array<std::uint32_t, 3>> triangles) {
  auto impl = std::make_shared<Solid::Impl>();
  impl->vertices = std::move(vertices);
  impl->triangles = std::move(triangles);
  detail::derive_properties(*impl);
  Solid solid;
  solid.impl_ = std::move(impl);
  return solid;
}

// A convex polyhedron's facets are strictly convex polygons, so the fan of
// each from its first corner has no zero-area triangle.
Solid Solid::from_polyhedron(const ConvexPolyhedron& polyhedron) {
  if (polyhedron.num_facets() == 0) return {};
  PolygonSoup soup = polyhedron.to_soup();
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) triangles.push_back({face[0], face[i], face[i + 1]});
  }
  return SolidAccess::assume_valid(std::move(soup.points), std::move(triangles));
}

PolygonSoup Solid::to_soup() const {
  PolygonSoup soup;
  if (!impl_) return soup;
  soup.points = impl_->vertices;
  soup.face_indices.reserve(impl_->triangles.size() * 3);
  soup.face_offsets.reserve(impl_->triangles.size() + 1);
  for (const auto& t : impl_->triangles) soup.add_face(t);
  return soup;
}

Location Solid::locate(const Vec3& p) const {
  if (!impl_) return Location::outside;
  const Impl& impl = *impl_;
  const detail::TriangleTree& tree = impl.tree();
  bool on_boundary = false;
  tree.for_each_overlapping(detail::point_box(p), [&](std::uint32_t t) {
    const auto& tri = impl.triangles[t];
    if (!on_boundary)
      on_boundary =
          detail::point_on_triangle(p, impl.vertices[tri[0]], impl.vertices[tri[1]], impl.vertices[tri[2]]);
  });
  if (on_boundary) return Location::boundary;
  const bool odd =
      detail::odd_crossings(tree, impl.vertices, impl.triangles, p, [](std::uint32_t) { return true; });
  return odd ? Location::inside : Location::outside;
}

Solid read_solid(const std::filesystem::path& path, const ReadLimits& limits) {
  // read_file's own errors already name the file (and the line).
  PolygonSoup soup = read_file(path, limits);
  try {
    return Solid::from_soup(std::move(soup));
  } catch (const Error& e) {
    throw Error(e.category(), path.string() + ": " + e.message());
  }
}

}  // namespace cvms
