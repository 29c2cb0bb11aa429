// SPDX-License-Identifier: MIT
// The checks and the ear clipping of face_triangulation.hpp.
//
// Order of the checks, each assuming the ones before: distinct corners; not
// all collinear (then the first two corners and some third span the plane);
// every corner on that plane (orient3d); in an exact chart of the plane
// (plane_chart.hpp, a bijection, so simplicity and turning are those of the
// face) no edge folds back onto its neighbour and no two other edges meet.
// A simple polygon whose corners are not all collinear has positive area.
//
// Ear clipping (ear_clipping.hpp) of the checked simple polygon: its corners
// are distinct, so every ear test is the plain one (no other corner in the
// closed triangle).
#include "face_triangulation.hpp"

#include <algorithm>
#include <string>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "ear_clipping.hpp"
#include "element_names.hpp"
#include "planar_tests.hpp"
#include "plane_chart.hpp"

namespace cvms::detail {

namespace {

[[noreturn]] void degenerate(const std::string& message) { throw Error(ErrorCategory::degenerate, message); }

class FaceCheck {
 public:
  FaceCheck(std::span<const Vec3> points, std::span<const std::uint32_t> ids,
            std::span<const std::uint32_t> names, std::uint32_t face)
      : points_(points), ids_(ids), names_(names), where_("face " + str(face)) {}

  // The plane's normal from the first two corners and a third not collinear with them.
  Vec3 spanning_normal(std::size_t& third) const {
    const Vec3& a = at(0);
    const Vec3 ab = at(1) - a;
    for (std::size_t j = 2; j < ids_.size(); ++j) {
      Vec3 n = cross(ab, at(j) - a);
      if (!is_zero(n)) {
        third = j;
        return n;
      }
    }
    degenerate(where_ + " has zero area (its vertices are collinear)");
  }

  void check_distinct() const {
    std::vector<std::uint32_t> sorted(ids_.begin(), ids_.end());
    std::sort(sorted.begin(), sorted.end());
    const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeated != sorted.end())
      degenerate(where_ + " uses vertex " + name(*repeated) + " more than once (not a simple polygon)");
  }

  void check_planar(std::size_t third) const {
    for (std::size_t j = 2; j < ids_.size(); ++j)
      if (orient3d(at(0), at(1), at(third), at(j)) != Sign::zero)
        degenerate(where_ + " is not planar: vertex " + name(ids_[j]) + " is off the plane of vertices " +
                   name(ids_[0]) + ", " + name(ids_[1]) + " and " + name(ids_[third]));
  }

  void check_simple(std::span<const Vec2> p) const {
    const std::size_t k = p.size();
    for (std::size_t i = 0; i < k; ++i) {
      const Vec2& prev = p[(i + k - 1) % k];
      const Vec2& next = p[(i + 1) % k];
      if (orient2(prev, p[i], next) == 0 && sign_dot(prev - p[i], next - p[i]) == Sign::positive)
        degenerate(where_ + " is not simple: it folds back at vertex " + name(ids_[i]));
    }
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = i + 2; j < k; ++j) {
        if (i == 0 && j == k - 1) continue;  // neighbours through corner 0
        if (segments_meet(p[i], p[i + 1], p[j], p[(j + 1) % k]))
          degenerate(where_ + " is not simple: its edges " + edge(i) + " and " + edge(j) + " meet");
      }
  }

  [[nodiscard]] std::string name(std::uint32_t id) const { return str(names_[id]); }
  [[nodiscard]] const std::string& where() const { return where_; }

 private:
  [[nodiscard]] const Vec3& at(std::size_t i) const { return points_[ids_[i]]; }
  [[nodiscard]] std::string edge(std::size_t i) const {
    return "(" + name(ids_[i]) + ", " + name(ids_[(i + 1) % ids_.size()]) + ")";
  }

  std::span<const Vec3> points_;
  std::span<const std::uint32_t> ids_;
  std::span<const std::uint32_t> names_;
  std::string where_;
};

}  // namespace

void triangulate_face(std::span<const Vec3> points, std::span<const std::uint32_t> ids,
                      std::span<const std::uint32_t> input_names, std::uint32_t face,
                      std::vector<std::array<std::uint32_t, 3>>& out, std::vector<Vec3>& areas) {
  const std::size_t k = ids.size();
  if (k < 3)
    degenerate("face " + str(face) + " has " + std::to_string(k) + " vertices (at least 3 are needed)");
  if (k > max_face_corners)
    throw Error(ErrorCategory::limit, "face " + str(face) + " has " + std::to_string(k) +
                                          " vertices; at most " + std::to_string(max_face_corners) +
                                          " are supported (the checks of a face are quadratic in its size)");
  const FaceCheck check(points, ids, input_names, face);
  check.check_distinct();
  std::size_t third = 2;
  const Vec3 normal = check.spanning_normal(third);
  if (k == 3) {
    out.push_back({ids[0], ids[1], ids[2]});
    areas.push_back(normal);
    return;
  }
  check.check_planar(third);
  const PlaneChart chart(normal);
  std::vector<Vec2> p;
  p.reserve(k);
  for (std::uint32_t id : ids) p.push_back(chart(points[id]));
  check.check_simple(p);
  Rational twice_area;
  for (std::size_t i = 0; i < k; ++i) twice_area += cross(p[i], p[(i + 1) % k]);
  std::vector<std::uint32_t> positions(k);
  for (std::uint32_t i = 0; i < k; ++i) positions[i] = i;
  std::vector<std::array<std::uint32_t, 3>> ears;
  EarClipper clipper(p, std::move(positions), sgn(twice_area));
  if (!clipper.run(ears)) degenerate(check.where() + " could not be triangulated without new vertices");
  for (const auto& [a, b, c] : ears) {
    out.push_back({ids[a], ids[b], ids[c]});
    const Vec3& pa = points[ids[a]];
    areas.push_back(cross(points[ids[b]] - pa, points[ids[c]] - pa));
  }
}

}  // namespace cvms::detail
