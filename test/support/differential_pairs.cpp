// SPDX-License-Identifier: MIT
#include "support/differential_pairs.hpp"

#include <map>
#include <utility>

#include "cvms/convex_hull.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"

namespace cvms::test {

namespace {

Vec3 q3(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

ConvexPolyhedron hull(const std::vector<Vec3>& points) { return convex_hull(points); }

// (x, y, z) -> (x, -z, y).
Mat3 quarter_turn_x() {
  Mat3 m;
  m.m[0][0] = 1;
  m.m[1][2] = -1;
  m.m[2][1] = 1;
  return m;
}

// One test's pairs are appended under the test's name.
class PairList {
 public:
  explicit PairList(std::vector<NamedPair>& out) : out_(out) {}
  void add(const std::string& test, const std::string& which, const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
    out_.push_back({test + ": " + which, a, b});
  }

 private:
  std::vector<NamedPair>& out_;
};

void hand_checked(PairList& l) {
  const auto t = shapes::tetrahedron();
  const auto c = shapes::cube();
  const auto o = shapes::octahedron();
  const auto tc = shapes::truncated_cube();
  l.add("CubePlusCube", "Cube + Cube", c, c);
  l.add("CubePlusAxisAlignedBox", "Cube + box", c, shapes::box(q3(0, 0, 0), q3(1, 2, Rational(7, 3))));
  l.add("SmallSums", "Tetra + Cube", t, c);
  l.add("SmallSums", "Tetra + Hedra", t, o);
  l.add("SmallSums", "Cube + Hedra", c, o);
  l.add("SmallSums", "Tetra + Tetra", t, t);
  l.add("SmallSums", "Tetra + -Tetra", t, t.reflected());
  for (int k = 1; k <= 3; ++k) {
    const auto s = shapes::geodesic_sphere(k);
    l.add("SumWithItself", "Sphere" + std::to_string(k) + " twice", s, s);
  }
  l.add("SumWithItself", "TruncatedCube twice", tc, tc);
  l.add("HomotheticCopies", "TruncatedCube + TruncatedCube/3", tc, scaled(tc, Rational(1, 3)));
  const auto s2 = shapes::geodesic_sphere(2);
  l.add("HomotheticCopies", "Sphere2 + 5 Sphere2", s2, scaled(s2, 5));
}

void paper_shapes(PairList& l) {
  const std::vector<std::pair<std::string, ConvexPolyhedron>> list = {
      {"Tetra", shapes::tetrahedron()},        {"Cube", shapes::cube()},
      {"Hedra", shapes::octahedron()},         {"TruncatedCube", shapes::truncated_cube()},
      {"Sphere1", shapes::geodesic_sphere(1)}, {"Sphere2", shapes::geodesic_sphere(2)},
      {"Sphere3", shapes::geodesic_sphere(3)},
  };
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t j = i; j < list.size(); ++j)
      l.add("PaperShapesEveryPair", list[i].first + " + " + list[j].first, list[i].second, list[j].second);
  l.add("RotatedSpheres", "Sphere2 + rot. Sphere2", shapes::geodesic_sphere(2), shapes::rotated_geodesic_sphere(2));
}

void parallel_features(PairList& l) {
  const auto c = shapes::cube();
  const auto t = shapes::tetrahedron();
  const auto tc = shapes::truncated_cube();
  l.add("CubePlusTruncatedCube", "Cube + TruncatedCube", c, tc);
  const auto p6 = shapes::prism(6, 1);
  const auto p8 = shapes::prism(8, Rational(5, 2));
  const auto p5 = shapes::prism(5, 3);
  const auto side = p5.transformed(quarter_turn_x(), {});
  l.add("PrismPlusPrism", "P6 + P8", p6, p8);
  l.add("PrismPlusPrism", "P5 + P8", p5, p8);
  l.add("PrismPlusPrism", "P6 + P6", p6, p6);
  l.add("PrismPlusPrism", "P6 + P5 on its side", p6, side);
  l.add("PrismPlusPrism", "P5 on its side + P8", side, p8);
  l.add("FacetOfAParallelToAnEdgeOfB", "Cube + Tetra", c, t);
  const auto r = hull(rhombic_dodecahedron_points());
  l.add("GaussianArcThroughAFacetNormal", "Cube + rhombic dodecahedron", c, r);
  l.add("GaussianArcThroughAFacetNormal", "TruncatedCube + rhombic dodecahedron", tc, r);
  l.add("PaperCriterionAlone", "Cube + tetrahedron",
        c, hull({q3(-2, 1, 3), q3(8, -4, -2), q3(-2, -4, -2), q3(-2, 6, -2)}));
  const auto o = shapes::octahedron();
  const auto box = shapes::box(q3(0, 0, 0), q3(1, 1, 2));
  const auto wedge = hull({q3(0, 0, 0), q3(2, 0, 0), q3(0, 2, 0), q3(0, 0, 2), q3(2, 0, 2), q3(0, 2, 2)});
  l.add("TiesOfContributingVertices", "Hedra + box", o, box);
  l.add("TiesOfContributingVertices", "wedge + box", wedge, box);
  l.add("TiesOfContributingVertices", "wedge + Hedra", wedge, o);
  l.add("TiesOfContributingVertices", "wedge + -wedge", wedge, wedge.reflected());
}

void far_huge_and_tiny(PairList& l) {
  const Rational g("1000000000");
  l.add("OperandsFarFromTheOrigin", "TruncatedCube + Sphere2",
        shapes::truncated_cube().translated(q3(g, 2 * g, -g)),
        shapes::geodesic_sphere(2).translated(q3(-3 * g, g + Rational(1, 3), 7 * g)));
  const auto c = shapes::cube().translated(q3(g, g, g));
  l.add("OperandsFarFromTheOrigin", "Cube + Cube", c, c);
  const Rational huge("1000000000000");
  const Rational tiny("1/1000000000000");
  const auto s = shapes::geodesic_sphere(2);
  const auto t = shapes::truncated_cube();
  for (const Rational& k : {huge, tiny}) {
    const std::string name = k == huge ? "huge" : "tiny";
    l.add("HugeAndTinyCoordinates", name + " Sphere2 + TruncatedCube", scaled(s, k), t);
    l.add("HugeAndTinyCoordinates", name + " Sphere2 + " + name + " TruncatedCube", scaled(s, k), scaled(t, k));
  }
  l.add("HugeAndTinyCoordinates", "huge Sphere2 + tiny TruncatedCube", scaled(s, huge), scaled(t, tiny));
}

void rotations_and_slabs(PairList& l) {
  const auto r1 = shapes::rational_rotation(1, 2, 3, 4);
  const auto cr = shapes::cube().transformed(r1, {});
  const auto tr = shapes::truncated_cube().transformed(r1, {});
  const auto or2 = shapes::octahedron().transformed(shapes::rational_rotation(2, -1, 0, 3), {});
  l.add("ExactRationalRotations", "rot. Cube + rot. TruncatedCube", cr, tr);
  l.add("ExactRationalRotations", "rot. Cube + TruncatedCube", cr, shapes::truncated_cube());
  l.add("ExactRationalRotations", "rot. TruncatedCube + rot. Hedra", tr, or2);
  l.add("ExactRationalRotations", "rot. Cube twice", cr, cr);
  const ThinOperands t = thin_operands();
  const auto s1 = shapes::geodesic_sphere(1);
  l.add("ThinSlabsAndNeedles", "slab + slab_y", t.slab, t.slab_y);
  l.add("ThinSlabsAndNeedles", "slab + needle", t.slab, t.needle);
  l.add("ThinSlabsAndNeedles", "needle + rot. needle", t.needle, t.needle_rotated);
  l.add("ThinSlabsAndNeedles", "slab + rot. slab", t.slab, t.slab_rotated);
  l.add("ThinSlabsAndNeedles", "rot. slab + Sphere1", t.slab_rotated, s1);
  l.add("ThinSlabsAndNeedles", "rot. needle + Sphere1", t.needle_rotated, s1);
  l.add("ThinSlabsAndNeedles", "tetra needle + rot. needle", t.tetra_needle, t.needle_rotated);
  const auto cube3 = ConvexPolyhedron::from_soup(triangulated_cube(3));
  l.add("InputTriangulated", "cube3 + TruncatedCube", cube3, shapes::truncated_cube());
  l.add("InputTriangulated", "cube3 + Cube", cube3, shapes::cube());
}

void arcs(PairList& l) {
  const auto c = shapes::cube();
  const auto tc = shapes::truncated_cube();
  const auto rotated = c.transformed(rotation_z_3_4_5(), {});
  const auto p6 = shapes::prism(6, 2);
  l.add("ArcsOverlapping", "Cube + octagonal prism", c, octagonal_prism());
  l.add("ArcsOverlapping", "Cube + rot. Cube", c, rotated);
  l.add("ArcsOverlapping", "box + rot. Cube", shapes::box(q3(0, 0, 0), q3(3, 1, Rational(1, 2))), rotated);
  l.add("ArcsOverlapping", "P6 + rot. P6", p6, p6.transformed(rotation_z_3_4_5(), {}));
  const auto b = hull({q3(1, 0, 0), q3(0, 1, 0), q3(Rational(1, 2), Rational(1, 2), 1), q3(-2, -5, -3)});
  const auto b2 = hull({q3(1, 0, 0), q3(0, 1, 0), q3(1, 0, 1), q3(-1, -2, -3)});
  const auto rot = shapes::rational_rotation(1, 2, 3, 4);
  l.add("ArcEndingOnAnotherArc", "Cube + B", c, b);
  l.add("ArcEndingOnAnotherArc", "Cube + B2", c, b2);
  l.add("ArcEndingOnAnotherArc", "rot. Cube + rot. B", c.transformed(rot, {}), b.transformed(rot, {}));
  l.add("ArcEndingOnAnotherArc", "TruncatedCube + B", tc, b);
  l.add("ArcEndingOnAnotherArc", "TruncatedCube + B2", tc, b2);
}

void flat_polyhedra(PairList& l) {
  const Rational h(1, 1000000);
  const auto flat = flat_bipyramid(h);
  const auto flat_rotated = flat.transformed(shapes::rational_rotation(1, 1, 2, 0), {});
  const auto tilted = flat.transformed(shapes::rational_rotation(100, 1, 0, 0), {});
  const auto flat_tetra = hull({q3(0, 0, 0), q3(1, 0, 0), q3(0, 1, 0), q3(Rational(1, 3), Rational(1, 3), h)});
  const auto slab = shapes::box(q3(0, 0, 0), q3(1000, 1000, Rational(1, 1000)));
  const std::string t = "FlatPolyhedra";
  l.add(t, "flat + Cube", flat, shapes::cube());
  l.add(t, "flat + -flat", flat, flat.reflected());
  l.add(t, "flat + rot. flat", flat, flat_rotated);
  l.add(t, "flat + tilted flat", flat, tilted);
  l.add(t, "flat tetra + -flat tetra", flat_tetra, flat_tetra.reflected());
  l.add(t, "flat tetra + flat", flat_tetra, flat);
  l.add(t, "slab + tilted flat", slab, tilted);
  l.add(t, "tilted flat + Sphere2", tilted, shapes::geodesic_sphere(2));
}

}  // namespace

std::vector<NamedPair> differential_pairs() {
  std::vector<NamedPair> out;
  PairList l(out);
  hand_checked(l);
  paper_shapes(l);
  parallel_features(l);
  far_huge_and_tiny(l);
  rotations_and_slabs(l);
  arcs(l);
  flat_polyhedra(l);
  return out;
}

ConvexPolyhedron scaled(const ConvexPolyhedron& p, const Rational& s) {
  return p.transformed(shapes::scaling(s, s, s), {});
}

// shapes_test checks that this quaternion gives cosine 3/5 and sine 4/5.
Mat3 rotation_z_3_4_5() { return shapes::rational_rotation(2, 0, 0, 1); }

ThinOperands thin_operands() {
  const Rational thin(1, 1000);
  ThinOperands t;
  t.slab = shapes::box(q3(0, 0, 0), q3(1000, 1000, thin));
  t.slab_y = shapes::box(q3(0, 0, 0), q3(1000, thin, 1000));
  t.needle = shapes::box(q3(0, 0, 0), q3(thin, thin, 1000));
  const Mat3 r = shapes::rational_rotation(1, 1, 2, 0);
  t.slab_rotated = t.slab.transformed(r, {});
  t.needle_rotated = t.needle.transformed(r, {});
  t.tetra_needle = hull({q3(0, 0, 0), q3(thin, 0, 0), q3(0, thin, 0), q3(1, 1, 1000)});
  return t;
}

ConvexPolyhedron flat_bipyramid(const Rational& h) {
  return hull({q3(2, 0, 0), q3(1, 2, 0), q3(-1, 2, 0), q3(-2, 0, 0), q3(-1, -2, 0), q3(1, -2, 0), q3(0, 0, h),
               q3(0, 0, -h)});
}

ConvexPolyhedron octagonal_prism() {
  std::vector<Vec3> points;
  for (int z : {1, -1}) {
    for (const auto& [x, y] : {std::pair{2, 1}, {1, 2}, {-1, 2}, {-2, 1}, {-2, -1}, {-1, -2}, {1, -2}, {2, -1}})
      points.push_back(q3(x, y, z));
  }
  return hull(points);
}

PolygonSoup triangulated_cube(int k) {
  PolygonSoup soup;
  std::map<Vec3, std::uint32_t> index;
  auto id = [&](const Vec3& p) {
    auto [it, inserted] = index.try_emplace(p, static_cast<std::uint32_t>(soup.points.size()));
    if (inserted) soup.points.push_back(p);
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side : {-1, 1}) {
      const int u = (axis + 1) % 3;
      const int w = (axis + 2) % 3;
      for (int i = -k; i < k; ++i) {
        for (int j = -k; j < k; ++j) {
          std::uint32_t q[4];
          const int du[4] = {0, 1, 1, 0};
          const int dw[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            Vec3 p;
            p[axis] = side * k;
            p[u] = i + du[c];
            p[w] = j + dw[c];
            q[c] = id(p);
          }
          // (u, w, axis) is right-handed: counterclockwise about +axis.
          if (side > 0) {
            soup.add_face({q[0], q[1], q[2]});
            soup.add_face({q[0], q[2], q[3]});
          } else {
            soup.add_face({q[0], q[2], q[1]});
            soup.add_face({q[0], q[3], q[2]});
          }
        }
      }
    }
  }
  return soup;
}

}  // namespace cvms::test
