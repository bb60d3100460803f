// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace disktune::detail {
namespace {

constexpr Rgb kBlack{0, 0, 0}, kWhite{255, 255, 255}, kGray{190, 190, 190};

/// A round tick step (1, 2 or 5 times a power of ten) giving about five ticks.
double tick_step(double span) {
  const double raw = span / 5, power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) return m * power;
  }
  return 10 * power;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

}  // namespace

Plot::Plot(int width, int height, double x0, double x1, double y0, double y1)
    : raster_(width, height, kWhite),
      left_(60),
      right_(width - 15),
      top_(15),
      bottom_(height - 30),
      x0_(x0),
      x1_(x1 > x0 ? x1 : x0 + 1),
      y0_(y0),
      y1_(y1 > y0 ? y1 : y0 + 1) {}

int Plot::px(double x) const {
  return left_ + static_cast<int>(std::lround((x - x0_) / (x1_ - x0_) * (right_ - left_)));
}
int Plot::py(double y) const {
  return bottom_ - static_cast<int>(std::lround((y - y0_) / (y1_ - y0_) * (bottom_ - top_)));
}

void Plot::axes() {
  // Clear the margins, so data clipped by nothing else ends at the frame.
  raster_.fill_rect(0, 0, raster_.width() - 1, top_ - 1, kWhite);
  raster_.fill_rect(0, bottom_ + 1, raster_.width() - 1, raster_.height() - 1, kWhite);
  raster_.fill_rect(0, 0, left_ - 1, raster_.height() - 1, kWhite);
  raster_.fill_rect(right_ + 1, 0, raster_.width() - 1, raster_.height() - 1, kWhite);
  raster_.line(left_, top_, right_, top_, kBlack);
  raster_.line(left_, bottom_, right_, bottom_, kBlack);
  raster_.line(left_, top_, left_, bottom_, kBlack);
  raster_.line(right_, top_, right_, bottom_, kBlack);
  const double sx = tick_step(x1_ - x0_), sy = tick_step(y1_ - y0_);
  for (double t = std::ceil(x0_ / sx - 1e-9) * sx; t <= x1_ + 1e-9 * sx; t += sx) {
    const int x = px(t);
    raster_.line(x, bottom_, x, bottom_ + 4, kBlack);
    const std::string s = number(t);
    raster_.text(x - Raster::text_width(s) / 2, bottom_ + 8, s, kBlack);
  }
  for (double t = std::ceil(y0_ / sy - 1e-9) * sy; t <= y1_ + 1e-9 * sy; t += sy) {
    const int y = py(t);
    raster_.line(left_ - 4, y, left_, y, kBlack);
    const std::string s = number(t);
    raster_.text(left_ - 7 - Raster::text_width(s), y - 3, s, kBlack);
  }
}

void Plot::reference(double y) {
  if (y < y0_ || y > y1_) return;
  for (int x = left_; x <= right_; x += 6)
    raster_.line(x, py(y), std::min(x + 3, right_), py(y), kGray);
}

void Plot::polyline(const std::vector<std::array<double, 2>>& points, Rgb color) {
  // Clamp y to just outside the area; axes() then clears the margins.
  auto y_of = [&](double y) { return std::clamp(py(y), top_ - 1, bottom_ + 1); };
  for (std::size_t i = 1; i < points.size(); ++i) {
    raster_.line(px(points[i - 1][0]), y_of(points[i - 1][1]), px(points[i][0]), y_of(points[i][1]),
                 color);
  }
}

void Plot::bar(double xa, double xb, double y, Rgb color) {
  const int a = px(xa), b = std::max(px(xb) - 1, a);
  raster_.fill_rect(a, py(0), b, std::max(py(y), top_), color);
}

}  // namespace disktune::detail
