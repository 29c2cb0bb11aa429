// SPDX-License-Identifier: MIT
#include "solid_sum_operands.hpp"

#include <array>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include "cvms/io.hpp"
#include "pieces_operands.hpp"

namespace cvms_bench {
namespace {

// The shipped operands' directory, set by bench/CMakeLists.txt.
const std::filesystem::path kBenchDataDir = CVMS_BENCH_DATA_DIR;

constexpr std::array<const char*, 4> kSmallSolids = {"l_block", "box_with_hole", "star_prism", "coarse_torus"};

// The comb polygon of k >= 2 teeth, counterclockwise seen from +z (see
// solid_sum_operand): along the base, up the last tooth, then down and up
// every gap and tooth back to the first.
std::vector<cvms::Vec3> comb_polygon(int k) {
  auto at = [](int x, int y) { return cvms::Vec3{cvms::Rational(x), cvms::Rational(y), cvms::Rational(0)}; };
  std::vector<cvms::Vec3> cycle = {at(0, 0), at(3 * k - 2, 0), at(3 * k - 2, 4), at(3 * k - 3, 4), at(3 * k - 3, 1)};
  for (int i = k - 2; i >= 1; --i)
    for (const cvms::Vec3& p : {at(3 * i + 1, 1), at(3 * i + 1, 4), at(3 * i, 4), at(3 * i, 1)}) cycle.push_back(p);
  for (const cvms::Vec3& p : {at(1, 1), at(1, 4), at(0, 4)}) cycle.push_back(p);
  return cycle;
}

// The prism over a counterclockwise polygon, z in [0, 1]: bottom, top, then
// one quad per polygon edge, each counterclockwise seen from outside.
cvms::Solid prism(const std::vector<cvms::Vec3>& cycle) {
  const auto n = static_cast<std::uint32_t>(cycle.size());
  cvms::PolygonSoup soup;
  for (const cvms::Vec3& p : cycle) soup.points.push_back(p);
  for (const cvms::Vec3& p : cycle) soup.points.push_back({p.x, p.y, cvms::Rational(1)});
  auto face = [&soup](std::initializer_list<std::uint32_t> indices) {
    soup.face_indices.insert(soup.face_indices.end(), indices);
    soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.face_indices.size()));
  };
  for (std::uint32_t i = n; i-- > 0;) soup.face_indices.push_back(i);
  soup.face_offsets.push_back(n);
  for (std::uint32_t i = 0; i < n; ++i) soup.face_indices.push_back(n + i);
  soup.face_offsets.push_back(2 * n);
  for (std::uint32_t i = 0; i < n; ++i) face({i, (i + 1) % n, n + (i + 1) % n, n + i});
  return cvms::Solid::from_soup(std::move(soup));
}

cvms::Solid load(std::string_view name) {
  if (name == "cube" || name == "coarse_torus") return cvms::read_solid(kBenchDataDir / (std::string(name) + ".off"));
  if (name.starts_with("comb")) return prism(comb_polygon(std::stoi(std::string(name.substr(4)))));
  return bench_solid(name);
}

std::vector<SolidPair> make_pairs() {
  std::vector<SolidPair> pairs;
  for (const char* s : kSmallSolids) pairs.push_back({std::string(s) + "+cube", s, "cube", PairGroup::small_cube});
  for (std::size_t i = 0; i < kSmallSolids.size(); ++i)
    for (std::size_t j = i + 1; j < kSmallSolids.size(); ++j)
      pairs.push_back({std::string(kSmallSolids[i]) + "+" + kSmallSolids[j], kSmallSolids[i], kSmallSolids[j],
                       PairGroup::small_small});
  pairs.push_back({"spot+icosphere", "spot", "icosphere", PairGroup::mesh});
  for (int k : kCombTeeth) {
    const std::string comb = "comb" + std::to_string(k);
    pairs.push_back({comb + "+cube", comb, "cube", PairGroup::comb, k});
  }
  return pairs;
}

}  // namespace

const std::vector<SolidPair>& solid_pairs() {
  static const std::vector<SolidPair> pairs = make_pairs();
  return pairs;
}

const cvms::Solid& solid_sum_operand(std::string_view name) {
  static std::map<std::string, cvms::Solid, std::less<>> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(std::string(name), load(name)).first;
  return it->second;
}

void write_operands(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::set<std::string> names;
  for (const SolidPair& pair : solid_pairs()) names.insert({pair.a, pair.b});
  for (const std::string& name : names) {
    const std::filesystem::path path = dir / (name + ".off");
    std::ofstream out(path, std::ios::binary);
    cvms::write_off(out, solid_sum_operand(name).to_soup());
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
}

std::vector<benchmark::internal::Benchmark*> register_solid_rows(const char* prefix, SolidPairRow row,
                                                                 bool (*keep)(const SolidPair&), bool two_threads) {
  std::vector<benchmark::internal::Benchmark*> rows;
  for (const SolidPair& pair : solid_pairs()) {
    if (!keep(pair)) continue;
    for (unsigned threads : {1U, 2U}) {
      if (threads > 1 && (!two_threads || pair.group != PairGroup::mesh)) continue;
      const std::string name = std::string(prefix) + "/" + pair.name + "/" + std::to_string(threads);
      auto* registered = benchmark::RegisterBenchmark(name.c_str(), row, pair, threads);
      registered->Unit(benchmark::kMillisecond);
      if (threads > 1) registered->UseRealTime();
      rows.push_back(registered);
    }
  }
  return rows;
}

}  // namespace cvms_bench
