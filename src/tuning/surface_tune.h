// SPDX-License-Identifier: GPL-3.0-or-later
// tune on a surface, with or without its final check (internal): a workflow that checks
// what it makes of the tuned packing once at its end (remesh) spares the exact scan of
// the whole surface and the copies kept for it, most of a small tune's time (the
// elephant at 10^4 disks, 200 injected: 0.075 s, 0.066 of it the check).
#pragma once

#include "disktune/surface_packing.h"
#include "disktune/tuning.h"

namespace disktune::detail {

/// tune(packing, target, rng, options), checked at the end where `final_check`.
TuneResult tune_surface(SurfacePacking& packing, const Target& target, Rng& rng,
                        const TuneOptions& options, bool final_check);

}  // namespace disktune::detail
