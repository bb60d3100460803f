// SPDX-License-Identifier: GPL-3.0-or-later
// Fixed disks laid out evenly along a stretch of a curve (internal), for every kind of
// domain: a planar domain's boundary segments and a surface's fixed curves (open
// boundary loops and sharp feature curves).
//
// Why evenly and at most kCurveSpacing r apart: two consecutive fixed disks closer than
// sqrt(2) r leave no room for another center in their diametral circle (a point at least
// r from both lies outside it), so no disk encroaches on the curve between them: their
// edge is in the (constrained or restricted) Delaunay mesh, and no interior disk sits
// close to the curve there. 1D darts leave steps up to 2r, which lets interior disks
// come within a sliver of the boundary.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "disktune/packing.h"
#include "disktune/sampling.h"
#include "disktune/surface_packing.h"

namespace disktune::detail {

/// Where a curve point lies in space.
inline Vec2 position(Vec2 p) { return p; }
inline Vec3 position(const SurfacePoint& p) { return p.p; }

/// How many step counts lay_out_evenly tries before it gives up on a stretch.
constexpr int kLayoutTries = 4;

/// Lays fixed disks out along a stretch u in [from, to] of a curve, evenly in the measure
/// ds / r(s): the fewest steps no wider than kCurveSpacing r, else one fewer (where a
/// site across a bend or near another curve came out covered), up to kLayoutTries
/// counts, while the steps stay below sqrt(2) r. Sites at `from` and `to` get a disk only when
/// place_from / place_to say so (else a disk is already there, or the stretch is closed and `to` is
/// `from`). A closed stretch starts at `from` + phase of a step.
///
///   at(u) -> P          the curve point at parameter u (P: Vec2 or SurfacePoint);
///   radius(P) -> double the sizing there;
///   place(P) -> DiskId  inserts a fixed disk there, or kNoDisk when a disk covers it;
///   remove(DiskId)      takes a placed disk out again.
///
/// `samples` (at least 8 per polyline piece of the stretch) sets how finely the measure
/// is integrated (midpoint rule, refined to 8 samples a step). Returns whether the
/// layout was placed; if not, nothing was.
template <class At, class Radius, class Place, class Remove>
bool lay_out_evenly(double from, double to, bool place_from, bool place_to, double phase,
                    std::size_t samples, At at, Radius radius, Place place, Remove remove) {
  // The cumulative measure on a uniform grid of u: chord length over the radius at the
  // chord's midpoint.
  std::vector<double> measure;
  auto integrate = [&](std::size_t n) {
    measure.assign(1, 0);
    auto previous = at(from);
    for (std::size_t k = 1; k <= n; ++k) {
      const auto next = at(from + (to - from) * static_cast<double>(k) / static_cast<double>(n));
      const auto middle =
          at(from + (to - from) * (static_cast<double>(k) - 0.5) / static_cast<double>(n));
      measure.push_back(measure.back() +
                        norm(position(next) - position(previous)) / radius(middle));
      previous = next;
    }
  };
  samples = std::max<std::size_t>(samples, 8);
  integrate(samples);
  if (const auto fine = 8 * static_cast<std::size_t>(std::ceil(measure.back())); fine > samples)
    integrate(fine);
  const std::size_t n = measure.size() - 1;
  const double total = measure.back();
  // The parameter u where the measure reaches m (linear between grid points).
  auto u_at = [&](double m) {
    const std::size_t k =
        std::min<std::size_t>(
            static_cast<std::size_t>(std::upper_bound(measure.begin(), measure.end(), m) -
                                     measure.begin()),
            n) -
        1;
    const double span = measure[k + 1] - measure[k];
    const double f = span > 0 ? std::clamp((m - measure[k]) / span, 0.0, 1.0) : 0;
    return from + (to - from) * (static_cast<double>(k) + f) / static_cast<double>(n);
  };
  // A few step counts at most: where the fewest fail, so do far fewer (a stretch that
  // meets another curve), and each try costs a pass over the stretch.
  std::vector<DiskId> placed;
  auto steps = static_cast<std::size_t>(std::ceil(total / kCurveSpacing));
  for (int tries = 0; tries < kLayoutTries && steps >= 1 &&
                      total / static_cast<double>(steps) < std::sqrt(2.0) * (1 - 1e-3);
       ++tries, --steps) {
    placed.clear();
    bool fits = true;
    for (std::size_t i = 0; i <= steps && fits; ++i) {
      if ((i == 0 && !place_from) || (i == steps && !place_to)) continue;
      const double m =
          std::min(total * (static_cast<double>(i) + phase) / static_cast<double>(steps), total);
      const DiskId id = place(at(u_at(m)));
      fits = id != kNoDisk;
      if (fits) placed.push_back(id);
    }
    if (fits) return true;
    for (const DiskId id : placed) remove(id);
  }
  return false;
}

}  // namespace disktune::detail
