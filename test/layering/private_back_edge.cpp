// SPDX-License-Identifier: MIT
// A private header of the minkowski layer: allowed in minkowski and above, a
// compile error below (see CMakeLists.txt here).
#include "stitch.hpp"

int cvms_layering_probe_private() { return 0; }
