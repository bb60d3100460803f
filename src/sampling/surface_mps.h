// SPDX-License-Identifier: GPL-3.0-or-later
// The surface MPS without its final check (internal), for a workflow that checks what it
// makes of the sample once at its end (remesh): the check is an exact scan of the whole
// surface, a fifth of the sampling's time.
#pragma once

#include <memory>

#include "disktune/random.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_sizing.h"

namespace disktune::detail {

/// sample_mps but for the check of the result (check_sample).
SurfacePacking sample_mps_unchecked(std::shared_ptr<const SurfaceDomain> domain,
                                    const SurfaceSizing& sizing, Rng& rng);

}  // namespace disktune::detail
