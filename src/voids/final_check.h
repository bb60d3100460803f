// SPDX-License-Identifier: GPL-3.0-or-later
// The last line of defence (internal): sample and tune check the packing they hand
// back with the exact checks once more (packing_defect: conflicts, then maximality),
// and a packing that fails is reported as a bug, never as success.
#pragma once

#include <string>

#include "disktune/errors.h"
#include "disktune/surface_voids.h"
#include "disktune/voids.h"

namespace disktune::detail {

/// What every failed final check ends its message with.
inline const char* const kReportBug =
    "This is a bug in disktune: please report it with the command or call that made it";

/// Throws InternalError, naming the defect, unless the sample is conflict-free and maximal.
template <class P>
void check_sample(const P& packing) {
  const std::string defect = packing_defect(packing);
  if (!defect.empty()) throw InternalError("sample: the sample failed the final check: " + defect + ". " + kReportBug);
}

}  // namespace disktune::detail
