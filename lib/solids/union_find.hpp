// SPDX-License-Identifier: MIT
// Disjoint sets of small integers (union-find with path halving), each
// class represented by its smallest member, so that numbering the classes
// in order of that member is deterministic.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace cvms::detail {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // The smaller root stays, so a class's root is its smallest member.
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  // Class numbers in order of their smallest member.
  std::vector<std::uint32_t> numbering(std::uint32_t& count) {
    std::vector<std::uint32_t> number(parent_.size());
    count = 0;
    for (std::uint32_t i = 0; i < parent_.size(); ++i) number[i] = find(i) == i ? count++ : number[find(i)];
    return number;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace cvms::detail
