// SPDX-License-Identifier: MIT
// What a user waits for before any sum: loading a polyhedron,
// i.e. parsing its exact OFF text and validating it (ConvexPolyhedron::
// from_soup: convexity, merging, planes). Two inputs: Sphere6 (20,480
// triangles, double coordinates written as their exact decimal expansions)
// and the hull of 35,000 random points with 6-digit decimal coordinates
// (like scanned meshes exported by Meshlab: every coordinate inexact in
// binary). The texts are made before the timed loop.
//
// Two more inputs where faces are coplanar in large groups: the surface of a
// box cut into 19,200 triangles or 9,600 quads (6 facets).
//
// And Sphere6 again, its doubles written as an exporter writes them
// (decimal_point.hpp): their shortest round-trip decimals, and 6 decimals.
// parse_numbers/<input> reads the coordinates of a Sphere6 text alone,
// each token exactly (try_parse_rational, as the readers do), and
// parse_numbers_double/<input> each to a double (std::from_chars): the
// floor a load is measured against.
//
// Rows: load/<input> (parse + validate, what read_polyhedron does),
// parse/<input> (read_off alone), validate/<input> (from_soup of the
// parsed soup, copied before each run outside the timing) and
// validate_and_planes/<input> (the same, then the facet planes made).
//
// And what a user waits for after a sum: write/<input> writes the exact OFF
// of Sphere6 and of Sphere6 + rotated Sphere6 (a 60,000-facet result) to
// memory, each from doubles and from decimals (Sphere6 read from its
// shortest and its 6-digit decimals, the sum of both spheres read from
// their shortest decimals), next to sum/Sphere6+rotated_Sphere6, the in-process sum it is
// the output of (writing should cost a small fraction of computing).
#include <benchmark/benchmark.h>

#include <charconv>
#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "decimal_point.hpp"

namespace {

using cvms::ConvexPolyhedron;
using cvms::PolygonSoup;

std::string off_text(const ConvexPolyhedron& p) {
  std::ostringstream out;
  cvms::write_off(out, p.to_soup());
  return out.str();
}

// Random points in the unit ball, each coordinate written with 6 decimals.
std::string decimal_hull_text(int n) {
  std::mt19937_64 rng(35000);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::string text;
  std::vector<cvms::Vec3> points;
  while (static_cast<int>(points.size()) < n) {
    const double x = unit(rng), y = unit(rng), z = unit(rng);
    if (x * x + y * y + z * z > 1.0) continue;
    points.push_back(cvms_bench::six_decimal_point(x, y, z));
  }
  return off_text(cvms::convex_hull(points));
}

// The surface of the cube [0, n]^3 cut into n x n unit squares per side, as
// quads or as two triangles each: a mesh whose faces are coplanar in large
// groups (6 facets in the end), which the filter alone cannot decide.
std::string tessellated_box_text(int n, bool triangles) {
  PolygonSoup soup;
  std::vector<std::uint32_t> index_of((n + 1) * (n + 1) * (n + 1), UINT32_MAX);
  const auto vertex = [&](int x, int y, int z) {
    std::uint32_t& i = index_of[(x * (n + 1) + y) * (n + 1) + z];
    if (i == UINT32_MAX) {
      i = static_cast<std::uint32_t>(soup.points.size());
      soup.points.push_back(cvms::Vec3{x, y, z});
    }
    return i;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int level : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::uint32_t corner[4];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            int c[3];
            c[axis] = level;
            c[(axis + 1) % 3] = i + du[k];
            c[(axis + 2) % 3] = j + dv[k];
            corner[level == n ? k : 3 - k] = vertex(c[0], c[1], c[2]);  // counterclockwise from outside
          }
          if (triangles) {
            soup.add_face({corner[0], corner[1], corner[2]});
            soup.add_face({corner[0], corner[2], corner[3]});
          } else {
            soup.add_face({corner[0], corner[1], corner[2], corner[3]});
          }
        }
  std::ostringstream out;
  cvms::write_off(out, soup);
  return out.str();
}

std::string sphere6_text(cvms_bench::TextForm form) {
  return cvms_bench::off_text(cvms::shapes::geodesic_sphere(6).to_soup(), form);
}

constexpr int num_inputs = 6;

const std::string& input(int which) {
  static const std::string texts[num_inputs] = {off_text(cvms::shapes::geodesic_sphere(6)),
                                                decimal_hull_text(35000),
                                                tessellated_box_text(40, true),
                                                tessellated_box_text(40, false),
                                                sphere6_text(cvms_bench::TextForm::shortest),
                                                sphere6_text(cvms_bench::TextForm::six_digits)};
  return texts[which];
}

const char* name(int which) {
  static const char* const names[num_inputs] = {"Sphere6",        "decimal_hull_35000",        "box_19200_triangles",
                                                "box_9600_quads", "Sphere6_shortest_decimals", "Sphere6_6_digits"};
  return names[which];
}

// The inputs that are Sphere6, in each of its written forms.
void sphere6_inputs(benchmark::internal::Benchmark* b) {
  b->Arg(0)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond);
}

// The coordinate tokens of an OFF text as write_off and off_text write it
// (a header line, a counts line, then one "x y z" line per point).
std::vector<std::string_view> coordinate_tokens(const std::string& text) {
  std::istringstream in(text);
  std::string header;
  std::size_t points = 0;
  in >> header >> points;
  std::vector<std::string_view> tokens;
  std::size_t at = text.find('\n', text.find('\n') + 1) + 1;
  while (tokens.size() < 3 * points) {
    while (text[at] == ' ' || text[at] == '\n') ++at;
    const std::size_t end = text.find_first_of(" \n", at);
    tokens.emplace_back(text.data() + at, end - at);
    at = end;
  }
  return tokens;
}

PolygonSoup parse(int which) {
  std::istringstream in(input(which));
  return cvms::read_off(in, name(which));
}

void BM_load(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  (void)input(which);
  for (auto _ : state) {
    std::istringstream in(input(which));
    ConvexPolyhedron p = cvms::to_polyhedron(cvms::read_off(in, name(which)), name(which));
    benchmark::DoNotOptimize(p.num_facets());
  }
  state.SetLabel(name(which));
}
BENCHMARK(BM_load)->DenseRange(0, num_inputs - 1)->Unit(benchmark::kMillisecond);

void BM_parse(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  (void)input(which);
  for (auto _ : state) {
    PolygonSoup soup = parse(which);
    benchmark::DoNotOptimize(soup.points.size());
  }
  state.SetLabel(name(which));
}
BENCHMARK(BM_parse)->DenseRange(0, num_inputs - 1)->Unit(benchmark::kMillisecond);

void BM_parse_numbers(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const std::vector<std::string_view> tokens = coordinate_tokens(input(which));
  for (auto _ : state)
    for (std::string_view token : tokens) {
      std::optional<cvms::Rational> value = cvms::try_parse_rational(token);
      benchmark::DoNotOptimize(value);
    }
  state.counters["numbers"] = static_cast<double>(tokens.size());
  state.SetLabel(name(which));
}
BENCHMARK(BM_parse_numbers)->Apply(sphere6_inputs);

void BM_parse_numbers_double(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const std::vector<std::string_view> tokens = coordinate_tokens(input(which));
  for (auto _ : state)
    for (std::string_view token : tokens) {
      double value = 0;
      std::from_chars(token.data(), token.data() + token.size(), value);
      benchmark::DoNotOptimize(value);
    }
  state.counters["numbers"] = static_cast<double>(tokens.size());
  state.SetLabel(name(which));
}
BENCHMARK(BM_parse_numbers_double)->Apply(sphere6_inputs);

// from_soup of the parsed input (copied outside the timing), then, with
// read_planes, one facet plane read: a loaded polyhedron makes its planes
// when first read (a sum reads them), so that row is what loading cost before
// they were made on demand, and what a user who sums a loaded operand still
// pays in total.
void validate(benchmark::State& state, bool read_planes) {
  const int which = static_cast<int>(state.range(0));
  const PolygonSoup soup = parse(which);
  for (auto _ : state) {
    state.PauseTiming();
    PolygonSoup copy = soup;
    state.ResumeTiming();
    ConvexPolyhedron p = ConvexPolyhedron::from_soup(std::move(copy));
    if (read_planes) benchmark::DoNotOptimize(&p.normal(cvms::FaceId(0)));
    benchmark::DoNotOptimize(p.num_facets());
  }
  state.SetLabel(name(which));
}

void BM_validate(benchmark::State& state) { validate(state, false); }
BENCHMARK(BM_validate)->DenseRange(0, num_inputs - 1)->Unit(benchmark::kMillisecond);

void BM_validate_and_planes(benchmark::State& state) { validate(state, true); }
BENCHMARK(BM_validate_and_planes)->DenseRange(0, num_inputs - 1)->Unit(benchmark::kMillisecond);

// What is written: Sphere6 and Sphere6 + rotated Sphere6 from doubles
// (dyadic coordinates), Sphere6 read from its shortest round-trip decimals
// and from its 6-digit decimals, and the sum of Sphere6 and rotated Sphere6
// both read from their shortest decimals (coordinates over powers of ten,
// and their sums).
constexpr int num_written = 5;

ConvexPolyhedron read_text(const std::string& text) {
  std::istringstream in(text);
  return cvms::to_polyhedron(cvms::read_off(in, "text"), "text");
}

const ConvexPolyhedron& written(int which) {
  static const ConvexPolyhedron sphere6 = cvms::shapes::geodesic_sphere(6);
  static const ConvexPolyhedron sum =
      cvms::minkowski_sum(sphere6, cvms::shapes::rotated_geodesic_sphere(6)).polyhedron;
  static const ConvexPolyhedron shortest = read_text(input(4));
  static const ConvexPolyhedron six_digits = read_text(input(5));
  static const ConvexPolyhedron shortest_sum =
      cvms::minkowski_sum(shortest, read_text(cvms_bench::off_text(cvms::shapes::rotated_geodesic_sphere(6).to_soup(),
                                                                   cvms_bench::TextForm::shortest)))
          .polyhedron;
  static const ConvexPolyhedron* const all[num_written] = {&sphere6, &sum, &shortest, &six_digits, &shortest_sum};
  return *all[which];
}

const char* written_name(int which) {
  static const char* const names[num_written] = {"Sphere6", "Sphere6+rotated_Sphere6", "Sphere6_shortest_decimals",
                                                 "Sphere6_6_digits",
                                                 "Sphere6+rotated_Sphere6_shortest_decimals"};
  return names[which];
}

void BM_write(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const PolygonSoup soup = written(which).to_soup();
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::ostringstream out;
    cvms::write_off(out, soup);
    bytes = out.str().size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["facets"] = static_cast<double>(written(which).num_facets());
  state.SetLabel(written_name(which));
}
BENCHMARK(BM_write)->DenseRange(0, num_written - 1)->Unit(benchmark::kMillisecond);

void BM_sum(benchmark::State& state) {
  const ConvexPolyhedron& a = written(0);
  const ConvexPolyhedron b = cvms::shapes::rotated_geodesic_sphere(6);
  for (auto _ : state) {
    ConvexPolyhedron sum = cvms::minkowski_sum(a, b).polyhedron;
    benchmark::DoNotOptimize(sum.num_facets());
  }
  state.SetLabel(written_name(1));
}
BENCHMARK(BM_sum)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
