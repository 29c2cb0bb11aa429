// SPDX-License-Identifier: MIT
#include "peer_qhalf.hpp"

#include <cstdio>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace cvms_bench {

QhalfResult qhull_halfspaces(std::span<const double> rows, const std::array<double, 3>& interior) {
  QhalfResult out;
  qhT context;
  qhT* qh = &context;
  qh_zero(qh, stderr);
  // 'Hx,y,z' gives the interior point; %.17g prints each double exactly
  // enough to read back the same double.
  char point[3 * 32];
  std::snprintf(point, sizeof point, "%.17g,%.17g,%.17g", interior[0], interior[1], interior[2]);
  std::string options = std::string("qhull H") + point;
  // With 'H', qhull maps the rows to new dual points it allocates itself and
  // (ismalloc == False) neither writes nor frees ours: the const_cast is safe.
  auto* coordinates = const_cast<coordT*>(rows.data());
  const int status = qh_new_qhull(qh, 4, static_cast<int>(rows.size() / 4), coordinates, False, options.data(),
                                  nullptr, stderr);
  if (status == 0) {
    out.vertices = static_cast<std::size_t>(qh->num_facets);
    out.rows = static_cast<std::size_t>(qh->num_vertices);
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  return out;
}

}  // namespace cvms_bench
