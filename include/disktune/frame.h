// SPDX-License-Identifier: GPL-3.0-or-later
// The axis-aligned rectangle a packing lives in, periodic (a torus) or not. Spatial
// grids and local geometry need only this, never the domain's shape, so planar
// domains with boundary reuse the same machinery with `periodic = false`.
#pragma once

#include <cmath>

#include "disktune/geometry.h"

namespace disktune {

struct Frame {
  Vec2 origin{0, 0};
  Vec2 extent{1, 1};
  bool periodic = true;

  /// For a periodic frame, the representative of `p` in [origin, origin + extent);
  /// otherwise `p` itself.
  Vec2 wrap(Vec2 p) const {
    if (!periodic) return p;
    return {wrap_1d(p.x, origin.x, extent.x), wrap_1d(p.y, origin.y, extent.y)};
  }

 private:
  static double wrap_1d(double v, double lo, double len) {
    double t = v - lo;
    t -= len * std::floor(t / len);
    if (t >= len) t = 0.0;  // v just below lo rounds up to len
    return lo + t;
  }
};

}  // namespace disktune
