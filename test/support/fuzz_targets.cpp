// SPDX-License-Identifier: MIT
// The fuzz target bodies (see fuzz_targets.hpp): byte decoders, the
// invariants checked after every accepted input, and the exact comparison of
// polyhedra used by the differential targets.
#include "support/fuzz_targets.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string_view>
#include <tuple>
#include <utility>

#include "cvms/convex_hull.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/set_sum.hpp"
#include "support/fuzz_bytes.hpp"
#include "support/set_oracle.hpp"

namespace cvms::fuzz {
namespace {

// ---- soup invariants and round trips (reader targets) ----

void check_soup(const PolygonSoup& soup, const ReadLimits& limits, const char* reader) {
  const std::string who = std::string(reader) + ": ";
  if (soup.face_offsets.empty() || soup.face_offsets.front() != 0 ||
      soup.face_offsets.back() != soup.face_indices.size())
    finding(who + "malformed face_offsets");
  if (soup.points.size() > limits.max_vertices) finding(who + "more points than max_vertices");
  if (soup.num_faces() > limits.max_faces) finding(who + "more faces than max_faces");
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (soup.face_offsets[f + 1] < soup.face_offsets[f] + 3) finding(who + "face with fewer than 3 indices");
    for (std::uint32_t v : soup.face(f))
      if (v >= soup.points.size()) finding(who + "face index out of range");
  }
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i) {
      if (!is_canonical(p[i])) finding(who + "non-canonical rational coordinate");
      if (mpz_sizeinbase(p[i].get_num_mpz_t(), 2) > limits.max_number_bits ||
          mpz_sizeinbase(p[i].get_den_mpz_t(), 2) > limits.max_number_bits)
        finding(who + "a coordinate beyond max_number_bits");
    }
}

// Rough size of the exact text of a soup, to keep round trips of inputs like
// "1e99999" (a 100000-digit integer from 7 bytes) affordable.
std::size_t exact_text_size(const PolygonSoup& soup) {
  std::size_t total = 0;
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i)
      total += mpz_sizeinbase(p[i].get_num_mpz_t(), 10) + mpz_sizeinbase(p[i].get_den_mpz_t(), 10);
  return total;
}

bool same_soup(const PolygonSoup& a, const PolygonSoup& b) {
  return a.points == b.points && a.face_offsets == b.face_offsets && a.face_indices == b.face_indices;
}

using Reader = PolygonSoup (*)(std::istream&, std::string_view, const ReadLimits&);
using Writer = void (*)(std::ostream&, const PolygonSoup&);

// Runs a reader; returns false if it rejected the input with an Error.
bool read_bytes(std::span<const std::uint8_t> data, Reader reader, const ReadLimits& limits,
                PolygonSoup& soup) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data.data()), data.size()));
  try {
    soup = reader(in, "<fuzz>", limits);
  } catch (const Error&) {
    return false;
  }
  return true;
}

void check_round_trip(const PolygonSoup& soup, Reader reader, Writer writer, const char* name) {
  std::ostringstream out;
  writer(out, soup);
  std::istringstream back(out.str());
  PolygonSoup again;
  try {
    again = reader(back, "<round trip>", ReadLimits{});
  } catch (const Error& e) {
    finding(std::string(name) + ": the written soup does not read back: " + e.what());
  }
  if (!same_soup(soup, again)) finding(std::string(name) + ": write + read changed the soup");
}

bool is_float_exact(const Rational& r) {
  if (!is_double_exact(r)) return false;
  const double d = to_double_nearest(r);
  const auto f = static_cast<float>(d);
  return static_cast<double>(f) == d;
}

// ---- exact comparison of polyhedra ----

struct Facet {
  Vec3 normal;
  Rational offset;
  std::vector<Vec3> vertices;  // sorted
  friend bool operator==(const Facet&, const Facet&) = default;
  friend bool operator<(const Facet& a, const Facet& b) {
    if (a.normal != b.normal) return a.normal < b.normal;
    if (a.offset != b.offset) return a.offset < b.offset;
    return a.vertices < b.vertices;
  }
};

struct Canonical {
  std::vector<Vec3> vertices;  // sorted
  std::vector<Facet> facets;   // sorted
  friend bool operator==(const Canonical&, const Canonical&) = default;
};

Canonical canonical(const ConvexPolyhedron& p) {
  Canonical c;
  const Mesh& m = p.mesh();
  for (VertexId v : m.vertices()) c.vertices.push_back(p.vertex(v));
  std::sort(c.vertices.begin(), c.vertices.end());
  for (FaceId f : m.faces()) {
    Facet facet{p.normal(f), p.plane_offset(f), {}};
    for (HalfedgeId h : m.face_halfedges(f)) facet.vertices.push_back(p.vertex(m.from(h)));
    std::sort(facet.vertices.begin(), facet.vertices.end());
    c.facets.push_back(std::move(facet));
  }
  std::sort(c.facets.begin(), c.facets.end());
  return c;
}

std::string describe(const Canonical& c) {
  return std::to_string(c.vertices.size()) + " vertices, " + std::to_string(c.facets.size()) + " facets";
}

// Independent plane check with plain rational arithmetic: every facet's
// normal is a primitive integer vector and every stored vertex satisfies the
// plane equation of every facet it is listed on.
void check_planes(const ConvexPolyhedron& p, const std::string& who) {
  const Mesh& m = p.mesh();
  for (FaceId f : m.faces()) {
    const Vec3& n = p.normal(f);
    mpz_class g = 0;
    for (int i = 0; i < 3; ++i) {
      if (n[i].get_den() != 1) finding(who + ": facet normal is not an integer vector");
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), n[i].get_num_mpz_t());
    }
    if (g != 1) finding(who + ": facet normal is not primitive");
    for (HalfedgeId h : m.face_halfedges(f))
      if (dot(n, p.vertex(m.from(h))) != p.plane_offset(f))
        finding(who + ": a facet vertex is off its plane");
  }
}

void check_convex(const ConvexPolyhedron& p, const std::string& who) {
  if (!p.is_convex()) finding(who + ": result fails is_convex()");
  check_planes(p, who);
}

void expect_same(const Canonical& a, const Canonical& b, const std::string& what) {
  if (!(a == b)) finding(what + ": " + describe(a) + " vs " + describe(b));
}

// ---- from_soup target ----

PolygonSoup reversed(const PolygonSoup& soup) {
  PolygonSoup r = soup;
  for (std::size_t f = 0; f < r.num_faces(); ++f)
    std::reverse(r.face_indices.begin() + r.face_offsets[f], r.face_indices.begin() + r.face_offsets[f + 1]);
  return r;
}

// The faces of a soup as separate index vectors, for editing.
std::vector<std::vector<std::uint32_t>> faces_of(const PolygonSoup& soup) {
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    faces.emplace_back(soup.face(f).begin(), soup.face(f).end());
  return faces;
}

PolygonSoup soup_of(std::vector<Vec3> points, const std::vector<std::vector<std::uint32_t>>& faces) {
  PolygonSoup soup;
  soup.points = std::move(points);
  for (const auto& f : faces) soup.add_face(f);
  return soup;
}

// The face (other than `skip`) that has the directed edge b -> a; or faces.size().
std::size_t face_with_edge(const std::vector<std::vector<std::uint32_t>>& faces, std::uint32_t b,
                           std::uint32_t a, std::size_t skip) {
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (f == skip) continue;
    const auto& face = faces[f];
    for (std::size_t i = 0; i < face.size(); ++i)
      if (face[i] == b && face[(i + 1) % face.size()] == a) return f;
  }
  return faces.size();
}

// A soup built from a hull by edits: `valid` stays true while every edit is
// one that from_soup must repair (triangulation, global flip, a vertex
// inserted on an edge or inside a face).
struct EditedSoup {
  PolygonSoup soup;
  bool valid = true;
};

EditedSoup edited_hull(ByteStream& in, const ConvexPolyhedron& hull) {
  PolygonSoup base = hull.to_soup();
  std::vector<Vec3> points = base.points;
  std::vector<std::vector<std::uint32_t>> faces = faces_of(base);
  bool valid = true;
  const std::uint8_t flags = in.next();
  if ((flags & 1) != 0) {  // fan-triangulate every face from a chosen corner
    std::vector<std::vector<std::uint32_t>> tri;
    for (const auto& f : faces) {
      const std::size_t s = in.next() % f.size();
      for (std::size_t k = 1; k + 1 < f.size(); ++k)
        tri.push_back({f[s], f[(s + k) % f.size()], f[(s + k + 1) % f.size()]});
    }
    faces = std::move(tri);
  }
  const int edits = in.next() % 5;
  for (int e = 0; e < edits && !faces.empty(); ++e) {
    const std::uint8_t op = in.next() % 8;
    const std::size_t f = in.next() % faces.size();
    auto& face = faces[f];
    const std::size_t i = in.next() % face.size();
    const auto n = static_cast<std::uint32_t>(points.size());
    switch (op) {
      case 0: {  // move a vertex by a small step: usually breaks convexity or planarity
        const std::uint32_t v = face[i];
        Vec3 step = decode_point(in, true);
        if (!is_zero(step)) valid = false;
        points[v] += fraction(1, 1 + in.next() % 4) * step;
        break;
      }
      case 1:  // flip one face
        std::reverse(face.begin(), face.end());
        valid = false;
        break;
      case 2:  // drop one face: a hole
        faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(f));
        valid = false;
        break;
      case 3: {  // a new vertex strictly inside an edge, inserted in both faces: repaired
        const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
        const std::size_t g = face_with_edge(faces, b, a, f);
        const long t = 1 + in.next() % 3;  // at t/4 of the edge
        points.push_back(points[a] + fraction(t, 4) * (points[b] - points[a]));
        face.insert(face.begin() + static_cast<std::ptrdiff_t>(i + 1), n);
        if (g < faces.size()) {
          auto& other = faces[g];
          for (std::size_t j = 0; j < other.size(); ++j)
            if (other[j] == b && other[(j + 1) % other.size()] == a) {
              other.insert(other.begin() + static_cast<std::ptrdiff_t>(j + 1), n);
              break;
            }
        } else {
          valid = false;  // an earlier edit removed the other side
        }
        break;
      }
      case 4: {  // a new vertex at the centroid of a face, the face fanned around it: repaired
        Vec3 c{0, 0, 0};
        for (std::uint32_t v : face) c += points[v];
        points.push_back(fraction(1, static_cast<long>(face.size())) * c);
        std::vector<std::uint32_t> old = face;
        faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(f));
        for (std::size_t k = 0; k < old.size(); ++k) faces.push_back({n, old[k], old[(k + 1) % old.size()]});
        break;
      }
      case 5: {  // a duplicate point taking over one corner
        points.push_back(points[face[i]]);
        face[i] = n;
        valid = false;
        break;
      }
      case 6:  // two corners of a face swapped
        std::swap(face[i], face[(i + 1 + in.next() % face.size()) % face.size()]);
        valid = false;
        break;
      default: {  // an unreferenced point
        points.push_back(decode_point(in, false));
        valid = false;
        break;
      }
    }
  }
  EditedSoup out{soup_of(std::move(points), faces), valid};
  if ((flags & 2) != 0) out.soup = reversed(out.soup);  // globally inward: repaired
  return out;
}

void check_accepted_soup(const PolygonSoup& soup, const ConvexPolyhedron& p) {
  check_convex(p, "from_soup");
  // Every point of an accepted soup is used by a face, so the result must be
  // the convex hull of all of them.
  ConvexPolyhedron hull;
  try {
    hull = convex_hull(soup.points);
  } catch (const Error& e) {
    finding(std::string("from_soup accepted a soup whose points have no 3D hull: ") + e.what());
  }
  const Canonical c = canonical(p);
  expect_same(c, canonical(hull), "from_soup differs from the hull of its points");
  ConvexPolyhedron flipped;
  try {
    flipped = ConvexPolyhedron::from_soup(reversed(soup));
  } catch (const Error& e) {
    finding(std::string("from_soup accepts a soup but rejects it reversed: ") + e.what());
  }
  expect_same(c, canonical(flipped), "from_soup of the reversed soup differs");
}

// ---- reader targets ----

void reader_target(std::span<const std::uint8_t> data, Reader reader, Writer writer, const char* name) {
  const ReadLimits limits = fuzz_limits();
  PolygonSoup soup;
  if (!read_bytes(data, reader, limits, soup)) return;
  check_soup(soup, limits, name);
  if (writer != nullptr && exact_text_size(soup) < (std::size_t{1} << 20))
    check_round_trip(soup, reader, writer, name);
}

void write_off_exact(std::ostream& out, const PolygonSoup& soup) { write_off(out, soup); }
void write_obj_exact(std::ostream& out, const PolygonSoup& soup) { write_obj(out, soup); }

}  // namespace

Rational decode_coordinate(std::uint8_t b) {
  // Numerators -15..16 over denominators 1 (5 in 8), 2, 3, 4: small enough
  // that coincidences (coplanar, parallel, collinear) are frequent, with
  // a few fractions so that non-integer offsets and normals appear.
  static constexpr int denominators[8] = {1, 1, 1, 1, 1, 2, 3, 4};
  return fraction(static_cast<long>(b & 0x1f) - 15, denominators[(b >> 5) & 7]);
}

ReadLimits fuzz_limits() {
  ReadLimits limits;
  limits.max_vertices = 100'000;
  limits.max_faces = 100'000;
  limits.max_bytes = std::uint64_t{1} << 20;
  limits.max_number_chars = 4096;
  return limits;
}

void read_off_target(std::span<const std::uint8_t> data) {
  reader_target(data, &read_off, &write_off_exact, "read_off");
}

void read_obj_target(std::span<const std::uint8_t> data) {
  reader_target(data, &read_obj, &write_obj_exact, "read_obj");
}

void read_stl_target(std::span<const std::uint8_t> data) {
  const ReadLimits limits = fuzz_limits();
  PolygonSoup soup;
  if (!read_bytes(data, &read_stl, limits, soup)) return;
  check_soup(soup, limits, "read_stl");
  // STL stores float32, so only a soup of float32 values survives a round trip.
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i)
      if (!is_float_exact(p[i])) return;
  check_round_trip(soup, &read_stl, &write_stl, "read_stl");
}

void write_ply_exact(std::ostream& out, const PolygonSoup& soup) { write_ply(out, soup); }
void write_ply_doubles(std::ostream& out, const PolygonSoup& soup) { write_ply(out, soup, Coordinates::double_); }

void read_ply_target(std::span<const std::uint8_t> data) {
  const ReadLimits limits = fuzz_limits();
  PolygonSoup soup;
  if (!read_bytes(data, &read_ply, limits, soup)) return;
  check_soup(soup, limits, "read_ply");
  if (exact_text_size(soup) >= (std::size_t{1} << 20)) return;
  // Binary PLY stores doubles: a soup of doubles survives it exactly.
  bool doubles = true;
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i) doubles = doubles && is_double_exact(p[i]);
  if (doubles) check_round_trip(soup, &read_ply, &write_ply_doubles, "read_ply (binary doubles)");
  // ASCII PLY is exact for coordinates with finite decimals, and refuses the others.
  try {
    std::ostringstream probe;
    write_ply(probe, soup);
  } catch (const Error& e) {
    if (e.category() != ErrorCategory::invalid_argument) throw;
    return;
  }
  check_round_trip(soup, &read_ply, &write_ply_exact, "read_ply (ASCII exact)");
}

void read_points_target(std::span<const std::uint8_t> data) {
  const ReadLimits limits = fuzz_limits();
  std::istringstream in(std::string(reinterpret_cast<const char*>(data.data()), data.size()));
  std::vector<Vec3> points;
  try {
    points = read_points(in, "<fuzz>", limits);
  } catch (const Error&) {
    return;
  }
  if (points.size() > limits.max_vertices) finding("read_points: more points than max_vertices");
  for (const Vec3& p : points)
    for (int i = 0; i < 3; ++i)
      if (!is_canonical(p[i])) finding("read_points: non-canonical rational coordinate");
}

void from_soup_target(std::span<const std::uint8_t> data) {
  ByteStream in(data);
  // mode: bit 0 raw faces / edited hull, bit 1 grid coordinates; for hulls,
  // bit 2 tiny moves, bit 3 an extreme scale.
  const std::uint8_t mode = in.next();
  const bool grid = (mode & 2) != 0;
  PolygonSoup soup;
  bool must_accept = false;
  if ((mode & 1) == 0) {
    // Raw: up to 24 points, then faces of 3..6 indices until the input ends.
    std::vector<Vec3> points = decode_cloud(in, 1 + in.next() % 24, grid);
    if (points.empty()) return;
    soup.points = std::move(points);
    const auto n = static_cast<std::uint32_t>(soup.points.size());
    std::vector<std::uint32_t> face;
    for (int f = 0; f < 64 && !in.empty(); ++f) {
      face.clear();
      const int deg = 3 + in.next() % 4;
      for (int k = 0; k < deg; ++k) face.push_back(in.next() % n);
      soup.add_face(face);
    }
  } else {
    // Edited hull: up to 31 points, their hull, then edits.
    std::vector<Vec3> points = decode_cloud(in, 4 + in.next() % 28, grid);
    if ((mode & 4) != 0) perturb_tiny(points, in);
    if ((mode & 8) != 0) scale_extreme(points, in);
    ConvexPolyhedron hull;
    try {
      hull = convex_hull(points);
    } catch (const Error&) {
      return;
    }
    check_convex(hull, "convex_hull");
    EditedSoup edited = edited_hull(in, hull);
    soup = std::move(edited.soup);
    must_accept = edited.valid;
  }
  ConvexPolyhedron p;
  try {
    p = ConvexPolyhedron::from_soup(soup);
  } catch (const Error& e) {
    if (must_accept) finding(std::string("from_soup rejects a repairable surface: ") + e.what());
    return;
  }
  check_accepted_soup(soup, p);
}

void minkowski_target(std::span<const std::uint8_t> data) {
  ByteStream in(data);
  // mode: bit 0 grid coordinates, bits 1-2 how B relates to A, bit 3 tiny
  // moves and an extreme scale, bit 4 B divided by 10^k (k < 40: decimals
  // whose common denominator is below 2^63 up to 10^18, below 2^124 (two
  // words) up to about 10^36, and beyond, for the sum's integer paths over
  // a common denominator in one word, in two, and the rational ones), bit 5
  // A divided by 2^j (61 <= j < 69: with bit 4, mixed dyadic and decimal
  // denominators such as 2^61 10^17).
  const std::uint8_t mode = in.next();
  const bool grid = (mode & 1) != 0;
  std::vector<Vec3> pa = decode_cloud(in, 4 + in.next() % 27, grid);
  std::vector<Vec3> pb;
  switch ((mode >> 1) & 3) {
    case 0:  // an independent cloud
      pb = decode_cloud(in, 4 + in.next() % 27, grid);
      break;
    case 1:  // -A: every facet of A has an antiparallel facet in B
      for (const Vec3& p : pa) pb.push_back(-p);
      break;
    case 2: {  // A scaled and translated: every facet direction shared
      const long num = 1 + in.next() % 3;
      const Rational s = fraction(num, 1 + in.next() % 2);
      const Vec3 t = decode_point(in, false);
      for (const Vec3& p : pa) pb.push_back(s * p + t);
      break;
    }
    default: {  // a subset of A plus a few new points: many shared directions
      for (const Vec3& p : pa)
        if ((in.next() & 1) != 0) pb.push_back(p);
      std::vector<Vec3> more = decode_cloud(in, in.next() % 6, grid);
      pb.insert(pb.end(), more.begin(), more.end());
      break;
    }
  }
  if ((mode & 8) != 0) {  // the same tiny moves and the same scale for both clouds
    const std::size_t at = pa.size();
    pa.insert(pa.end(), pb.begin(), pb.end());
    perturb_tiny(pa, in);
    scale_extreme(pa, in);
    pb.assign(pa.begin() + static_cast<std::ptrdiff_t>(at), pa.end());
    pa.resize(at);
  }
  if ((mode & 16) != 0) {
    mpz_class power;
    mpz_ui_pow_ui(power.get_mpz_t(), 10, in.next() % 40);
    const Rational scale(mpz_class(1), power);
    for (Vec3& p : pb) p = scale * p;
  }
  if ((mode & 32) != 0) {
    const Rational scale(mpz_class(1), mpz_class(1) << (61 + in.next() % 8));
    for (Vec3& p : pa) p = scale * p;
  }
  ConvexPolyhedron a, b;
  try {
    a = convex_hull(pa);
    b = convex_hull(pb);
  } catch (const Error&) {
    return;  // degenerate clouds
  }
  check_convex(a, "convex_hull(A)");
  check_convex(b, "convex_hull(B)");

  // CHMS is the reference; it is not re-verified on its own (is_convex is
  // O(V F)): CVMS's result is, and the two must be identical.
  const ConvexPolyhedron reference = minkowski_sum(a, b, with(Algorithm::chms)).polyhedron;
  check_planes(reference, "chms");
  const Canonical expected = canonical(reference);

  const MinkowskiResult cvms_ab = minkowski_sum(a, b, with(Algorithm::cvms));
  check_convex(cvms_ab.polyhedron, "cvms(A, B)");
  expect_same(canonical(cvms_ab.polyhedron), expected, "cvms(A, B) differs from chms(A, B)");
  const Stats& s = cvms_ab.stats;
  if (s.translated_facets + s.corner_facets + s.edge_facets != cvms_ab.polyhedron.num_facets())
    finding("cvms stats: translated + corner + edge facets != facets of the result");

  const ConvexPolyhedron cvms_ba = minkowski_sum(b, a, with(Algorithm::cvms)).polyhedron;
  expect_same(canonical(cvms_ba), expected, "cvms(B, A) differs from chms(A, B)");

  const ConvexPolyhedron essdms = minkowski_sum(a, b, with(Algorithm::essdms)).polyhedron;
  check_convex(essdms, "essdms(A, B)");
  expect_same(canonical(essdms), expected, "essdms(A, B) differs from chms(A, B)");
}

void sets_target(std::span<const std::uint8_t> data) {
  ByteStream in(data);
  const ConvexSet a = decode_set(in);
  const ConvexSet b = decode_set(in);
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms, Algorithm::chms}) {
    // check_set_sum: both orders, the representation's invariants, and the
    // hull of the pairwise vertex sums (support/set_oracle.hpp), exactly.
    std::string bad;
    try {
      bad = test::check_set_sum(a, b, with(algorithm));
    } catch (const Error& e) {  // no input of this size may be refused
      bad = std::string("threw ") + e.what();
    }
    if (!bad.empty())
      finding("minkowski_sum of sets (dimensions " + std::to_string(a.dimension()) + ", " +
              std::to_string(b.dimension()) + ", " + to_string(algorithm) + "): " + bad);
  }
}

Target target_by_name(const std::string& name) {
  if (name == "read_off") return &read_off_target;
  if (name == "read_obj") return &read_obj_target;
  if (name == "read_stl") return &read_stl_target;
  if (name == "read_ply") return &read_ply_target;
  if (name == "read_points") return &read_points_target;
  if (name == "from_soup") return &from_soup_target;
  if (name == "minkowski") return &minkowski_target;
  if (name == "sets") return &sets_target;
  if (name == "read_halfspaces") return &read_halfspaces_target;
  if (name == "halfspaces") return &halfspaces_target;
  if (name == "read_pieces") return &read_pieces_target;
  if (name == "read_solid") return &read_solid_target;
  if (name == "solid_sum") return &solid_sum_target;
  return nullptr;
}

std::vector<std::string> target_names() {
  return {"read_off", "read_obj",        "read_stl",   "read_ply",    "read_points", "from_soup", "minkowski",
          "sets",     "read_halfspaces", "halfspaces", "read_pieces", "read_solid",  "solid_sum"};
}

}  // namespace cvms::fuzz
