// SPDX-License-Identifier: MIT
#include "peer_qhull.hpp"

#include <cstdio>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace cvms_bench {

QhullHull qhull_hull(std::span<const double> xyz) {
  QhullHull out;
  qhT context;
  qhT* qh = &context;
  qh_zero(qh, stderr);
  // qhull only reads the points (no scaling option is given) and, with
  // ismalloc == False, never frees them: the const_cast is safe.
  char options[] = "qhull";
  auto* points = const_cast<coordT*>(xyz.data());
  const int status =
      qh_new_qhull(qh, 3, static_cast<int>(xyz.size() / 3), points, False, options, nullptr, stderr);
  if (status == 0) {
    out.facets = static_cast<std::size_t>(qh->num_facets);
    out.vertices = static_cast<std::size_t>(qh->num_vertices);
    // Short memory comes in buffers that are kept until the end, so the
    // buffers' total is their peak; long memory has its own maximum.
    out.peak_bytes =
        static_cast<std::size_t>(qh->qhmem.maxlong) + static_cast<std::size_t>(qh->qhmem.totbuffer);
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  return out;
}

}  // namespace cvms_bench
