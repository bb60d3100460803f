// SPDX-License-Identifier: GPL-3.0-or-later
// Line plots and bar charts on a Raster (internal): a frame with numbered ticks and a
// map from data to pixels, enough for the report's pictures.
#pragma once

#include <array>
#include <vector>

#include "raster.h"

namespace disktune::detail {

class Plot {
 public:
  /// A white width x height picture whose plot area shows [x0, x1] x [y0, y1].
  Plot(int width, int height, double x0, double x1, double y0, double y1);

  /// The frame, ticks at round steps and their numbers; call after drawing the data.
  void axes();
  /// A horizontal reference line at y (light gray), under the data.
  void reference(double y);
  /// Line segments through the points (clipped to the plot area).
  void polyline(const std::vector<std::array<double, 2>>& points, Rgb color);
  /// A bar over [xa, xb] from 0 up to y.
  void bar(double xa, double xb, double y, Rgb color);

  const Raster& raster() const { return raster_; }

 private:
  int px(double x) const;
  int py(double y) const;

  Raster raster_;
  int left_, right_, top_, bottom_;  // the plot area in pixels
  double x0_, x1_, y0_, y1_;
};

}  // namespace disktune::detail
