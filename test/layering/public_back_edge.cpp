// SPDX-License-Identifier: MIT
// A public header of the minkowski layer: allowed in minkowski and above, a
// compile error below (see CMakeLists.txt here).
#include "cvms/minkowski.hpp"

int cvms_layering_probe_public() { return static_cast<int>(cvms::Algorithm::cvms); }
