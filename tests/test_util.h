// SPDX-License-Identifier: GPL-3.0-or-later
// Glue between the library and the independent oracle: the oracle sees plain numbers.
#pragma once

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "oracle/oracle.h"

namespace disktune::test {

inline oracle::Points centers_of(const Packing& packing) {
  oracle::Points out;
  for (DiskId id : packing.ids()) out.push_back({packing.center(id).x, packing.center(id).y});
  return out;
}

inline oracle::Box box_of(const PeriodicBox& box) { return {box.width(), box.height()}; }

}  // namespace disktune::test
