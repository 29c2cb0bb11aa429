// SPDX-License-Identifier: MIT
// The fuzz targets of the non-convex paths (fuzz_targets.hpp): the pieces
// reader, the solid reader and the sum of solids as one solid. Each accepted input is checked against what
// the library promises, with the test's own exact arithmetic where it can.
#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "cvms/solid.hpp"
#include "cvms/solid_sum.hpp"
#include "cvms/union_io.hpp"
#include "support/fuzz_targets.hpp"
#include "support/union_oracle.hpp"
#include "support/voxel_oracle.hpp"

namespace cvms::fuzz {
namespace {

[[noreturn]] void finding(const std::string& what) { throw FuzzFinding(what); }

std::string text_of(std::span<const std::uint8_t> data) {
  return std::string(reinterpret_cast<const char*>(data.data()), data.size());
}

// Cubes of an nx x ny x nz grid, one bit each from `data` from bit `first`
// on (missing bits are 0).
test::Cubes decode_cubes(std::span<const std::uint8_t> data, std::size_t first, int nx, int ny, int nz) {
  test::Cubes cubes;
  std::size_t bit = first;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k, ++bit)
        if (bit / 8 < data.size() && ((data[bit / 8] >> (bit % 8)) & 1) != 0) cubes.insert({i, j, k});
  return cubes;
}

// The polycube as a solid (cubes meeting only along an edge or at a corner
// too: their faces then share that edge or point by index), or nothing when
// empty; every non-empty polycube is a solid, so a refusal is a finding.
std::optional<Solid> polycube_solid(const test::Cubes& cubes) {
  if (cubes.empty()) return std::nullopt;
  try {
    return Solid::from_soup(test::polycube_soup(cubes));
  } catch (const Error& e) {
    finding(std::string("solid_sum: a polycube is refused as a solid: ") + e.what());
  }
}

// The sum written as OFF reads back as the same solid (touching parts keep
// a vertex per shell).
void expect_read_back(const Solid& sum) {
  std::ostringstream out;
  write_off(out, sum.to_soup());
  std::istringstream in(out.str());
  Solid back;
  try {
    back = Solid::from_soup(read_off(in, "<written sum>"));
  } catch (const Error& e) {
    finding(std::string("solid_sum: the written sum does not read back: ") + e.what());
  }
  std::vector<Vec3> written(sum.vertices().begin(), sum.vertices().end());
  std::vector<Vec3> read(back.vertices().begin(), back.vertices().end());
  std::sort(written.begin(), written.end());
  std::sort(read.begin(), read.end());
  if (back.volume() != sum.volume() || read != written || back.num_shells() != sum.num_shells() ||
      back.num_facets() != sum.num_facets())
    finding("solid_sum: the written sum reads back as another solid");
}

}  // namespace

void solid_sum_target(std::span<const std::uint8_t> data) {
  if (data.empty()) return;
  // Byte 0: bit 0 picks B (a box, or a polycube of a 2 x 2 x 2 grid), bits
  // 1-5 the box's sides, bit 6 two threads. Then A's cubes (3 x 3 x 2 grid),
  // then B's.
  const std::uint8_t mode = data[0];
  const test::Cubes a_cubes = decode_cubes(data, 8, 3, 3, 2);
  const test::Cubes b_cubes =
      (mode & 1) != 0 ? decode_cubes(data, 8 + 18, 2, 2, 2)
                      : test::box_cubes(1 + ((mode >> 1) & 1), 1 + ((mode >> 2) & 3), 1 + ((mode >> 4) & 1));
  const std::optional<Solid> a = polycube_solid(a_cubes), b = polycube_solid(b_cubes);
  if (!a || !b) return;
  Options options;
  options.threads = (mode & 64) != 0 ? 2 : 1;
  Solid sum;
  try {
    sum = minkowski_sum(*a, *b, options);
  } catch (const Error& e) {
    finding(std::string("solid_sum: two valid polycubes do not sum: ") + e.what());
  }
  const test::Cubes expected = test::polycube_sum(a_cubes, b_cubes);
  if (sum.volume() != Rational(static_cast<long>(expected.size())))
    finding("solid_sum: the volume is not the voxel count");
  std::set<Vec3> corners;
  for (const test::Cube& g : test::voxel_vertices(expected)) corners.insert(test::mapped_point(g, {}));
  if (std::set<Vec3>(sum.vertices().begin(), sum.vertices().end()) != corners)
    finding("solid_sum: the vertices are not the voxels' corners");
  if (sum.num_facets() != test::voxel_facets(expected)) finding("solid_sum: the facets are not the voxels'");
  expect_read_back(sum);
}

void read_pieces_target(std::span<const std::uint8_t> data) {
  std::istringstream in(text_of(data));
  ConvexUnion pieces;
  try {
    pieces = read_pieces(in, "<fuzz>", fuzz_limits());
  } catch (const Error&) {
    return;
  }
  if (pieces.empty()) finding("read_pieces: accepted a file without pieces");
  for (const ConvexPolyhedron& piece : pieces.pieces())
    if (!piece.is_convex() || test::volume_by_tetrahedra(piece) <= 0) finding("read_pieces: a piece is not a convex body");
  std::ostringstream out;
  write_pieces(out, pieces);
  std::istringstream back(out.str());
  ConvexUnion again;
  try {
    again = read_pieces(back, "<round trip>");
  } catch (const Error& e) {
    finding(std::string("read_pieces: the written pieces do not read back: ") + e.what());
  }
  if (again.size() != pieces.size()) finding("read_pieces: write + read changed the number of pieces");
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (test::vertex_set(again.pieces()[i]) != test::vertex_set(pieces.pieces()[i]))
      finding("read_pieces: write + read changed piece " + std::to_string(i));
}

void read_solid_target(std::span<const std::uint8_t> data) {
  std::istringstream in(text_of(data));
  Solid solid;
  try {
    solid = Solid::from_soup(read_off(in, "<fuzz>", fuzz_limits()));
  } catch (const Error&) {
    return;
  }
  if (solid.volume() <= 0) finding("read_solid: accepted a solid without positive volume");
  if (solid.is_convex() != (solid.num_reflex_edges() == 0 && solid.num_shells() == 1))
    finding("read_solid: is_convex disagrees with the reflex edges and shells");
  if (solid.triangles().size() > 64) return;  // the decomposition of small solids only
  ConvexUnion pieces;
  try {
    pieces = convex_decomposition(solid);
  } catch (const Error& e) {
    finding(std::string("read_solid: a valid solid does not decompose: ") + e.what());
  }
  Rational total = 0;
  for (const ConvexPolyhedron& piece : pieces.pieces()) total += test::volume_by_tetrahedra(piece);
  if (total != solid.volume()) finding("read_solid: the pieces' volumes do not sum to the solid's");
}

}  // namespace cvms::fuzz
