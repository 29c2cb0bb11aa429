// SPDX-License-Identifier: MIT
#include "lazy_positions.hpp"

#include <cstdlib>

namespace cvms::detail {

void LazyPositions::make_vectors() const {
  // Built in place: moving an mpq_class re-initialises the source, which allocates.
  std::vector<Vec3> vectors(packed_.size());
  LimbArena limbs;
  for (std::size_t j = 0; j < vectors.size(); ++j) {
    for (int axis = 0; axis < 3; ++axis) {
      const PackedDyadic& c = packed_.coordinate(j, axis);
      limbs.store_dyadic(vectors[j][axis], c.limbs(), static_cast<std::size_t>(std::abs(c.size)), c.size < 0,
                         c.exponent);
    }
  }
  // Nothing above changed this object, so a throw leaves it as it was.
  made_limbs_ = std::move(limbs);
  vectors_ = std::move(vectors);
}

}  // namespace cvms::detail
