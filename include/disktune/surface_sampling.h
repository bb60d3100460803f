// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling of a curved surface (paper, section 7.2). The fixed curves
// (open boundary, sharp features) are sampled first with fixed disks and stay.
#pragma once

#include <memory>

#include "disktune/random.h"
#include "disktune/sampling.h"
#include "disktune/surface_packing.h"

namespace disktune {

/// A maximal Poisson-disk sample of the surface: fixed disks first (one on each feature
/// corner, each feature curve laid out evenly kCurveSpacing r apart where that fits,
/// then 1D darts over what is left uncovered of the fixed curves), then darts over the
/// surface by area and over ever smaller cells around the uncovered part, then one disk
/// at a uniform point of each void left (never at a void's vertex, which would bias the
/// spacing). Conflict-free and maximal; ids follow a spatial order
/// (SurfacePacking::order_by_place).
SurfacePacking sample_mps(std::shared_ptr<const SurfaceDomain> domain,
                                  const SurfaceSizing& sizing, Rng& rng);

}  // namespace disktune
