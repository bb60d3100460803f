// SPDX-License-Identifier: GPL-3.0-or-later
// Line plots and bar charts on a Drawing (internal): a frame with numbered ticks, a
// title, axis titles and a legend, and a map from data to pixels; the report's and the
// fiber statistics' pictures.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "drawing.h"

namespace disktune::detail {

struct PlotText {
  std::string title, x_axis, y_axis;
};

class Plot {
 public:
  /// A white width x height picture whose plot area shows [x0, x1] x [y0, y1].
  Plot(int width, int height, double x0, double x1, double y0, double y1, PlotText text);

  /// The frame, ticks at round steps and their numbers, the titles and the legend; call
  /// after drawing the data.
  void axes();
  /// A dashed horizontal reference line at y, under the data, named in the legend.
  void reference(double y, Rgb color, const std::string& name);
  /// Line segments through the points (clipped to the plot area), named in the legend
  /// unless `name` is empty.
  void polyline(const std::vector<std::array<double, 2>>& points, Rgb color, const std::string& name = {});
  /// A bar over [xa, xb] from 0 up to y.
  void bar(double xa, double xb, double y, Rgb color);

  const Drawing& drawing() const { return drawing_; }
  Drawing& drawing() { return drawing_; }

 private:
  double px(double x) const;
  double py(double y) const;

  struct Entry {
    std::string name;
    Rgb color;
    bool dashed;
  };
  Drawing drawing_;
  PlotText text_;
  std::vector<Entry> legend_;
  int left_, right_, top_, bottom_;  // the plot area in pixels
  double x0_, x1_, y0_, y1_;
};

}  // namespace disktune::detail
