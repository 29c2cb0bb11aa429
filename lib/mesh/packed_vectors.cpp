// SPDX-License-Identifier: MIT
#include "packed_vectors.hpp"

#include <cstdlib>

namespace cvms::detail {

void PackedVectors::make_vectors() const {
  // Built in place (moving an mpq_class re-initialises the source, which
  // allocates), each denominator's heap limb given back as soon as it is
  // made, so that the whole array reuses one heap block.
  std::vector<Vec3> vectors;
  vectors.reserve(size());
  LimbArena limbs;
  if (is_scaled_) {
    for (std::size_t j = 0; j < scaled_.size(); ++j) {
      Vec3& v = vectors.emplace_back();
      for (int axis = 0; axis < 3; ++axis) scaled_.store(j, axis, limbs, v[axis]);
    }
  }
  for (std::size_t j = 0; j < packed_.size(); ++j) {
    Vec3& v = vectors.emplace_back();
    for (int axis = 0; axis < 3; ++axis) {
      LimbArena::give_back_denominator(v[axis]);
      const PackedDyadic& c = packed_.coordinate(j, axis);
      limbs.store_dyadic(v[axis], c.limbs(), static_cast<std::size_t>(std::abs(c.size)), c.size < 0, c.exponent);
    }
  }
  // Nothing above changed this object, so a throw leaves it as it was.
  made_limbs_ = std::move(limbs);
  vectors_ = std::move(vectors);
}

}  // namespace cvms::detail
