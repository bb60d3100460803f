// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace disktune::detail {
namespace {

constexpr Rgb kBlack{0, 0, 0}, kWhite{255, 255, 255};
constexpr double kNumberSize = 11, kLabelSize = 13, kTitleSize = 15;

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

Plot::Plot(int width, int height, double x0, double x1, double y0, double y1, PlotText text)
    : drawing_(width, height, kWhite),
      text_(std::move(text)),
      left_(72),
      right_(width - 15),
      top_(34),
      bottom_(height - 46),
      x0_(x0),
      x1_(x1 > x0 ? x1 : x0 + 1),
      y0_(y0),
      y1_(y1 > y0 ? y1 : y0 + 1) {}

double Plot::px(double x) const { return left_ + (x - x0_) / (x1_ - x0_) * (right_ - left_); }
double Plot::py(double y) const { return bottom_ - (y - y0_) / (y1_ - y0_) * (bottom_ - top_); }

void Plot::axes() {
  Drawing& r = drawing_;
  r.unclip();
  const double l = left_ + 0.5, rt = right_ + 0.5, t = top_ + 0.5, b = bottom_ + 0.5;
  r.polyline({{l, t}, {rt, t}, {rt, b}, {l, b}, {l, t}}, kBlack, 1);
  const double sx = tick_step(x1_ - x0_), sy = tick_step(y1_ - y0_);
  for (double v = std::ceil(x0_ / sx - 1e-9) * sx; v <= x1_ + 1e-9 * sx; v += sx) {
    const double x = std::round(px(v)) + 0.5;
    r.line(x, b, x, b + 4, kBlack);
    r.text(x, b + 17, number(v), kNumberSize, kBlack, Drawing::Align::center);
  }
  for (double v = std::ceil(y0_ / sy - 1e-9) * sy; v <= y1_ + 1e-9 * sy; v += sy) {
    const double y = std::round(py(v)) + 0.5;
    r.line(l - 4, y, l, y, kBlack);
    r.text(l - 7, y + 4, number(v), kNumberSize, kBlack, Drawing::Align::right);
  }
  r.text((left_ + right_) / 2.0, top_ - 12, text_.title, kTitleSize, kBlack,
         Drawing::Align::center);
  r.text((left_ + right_) / 2.0, r.height() - 10, text_.x_axis, kLabelSize, kBlack,
         Drawing::Align::center);
  r.text(18, (top_ + bottom_) / 2.0, text_.y_axis, kLabelSize, kBlack, Drawing::Align::center,
         true);
  if (legend_.empty()) return;
  // Top right inside the frame, on white: a line sample and the name of each entry.
  double widest = 0;
  for (const Entry& e : legend_) widest = std::max(widest, r.text_width(e.name, kNumberSize));
  const double row = 16, x1 = right_ - 6, x0 = x1 - widest - 40, y0 = top_ + 6;
  r.fill_rect(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1), static_cast<int>(y0 + row * legend_.size() + 6),
              kWhite);
  for (std::size_t k = 0; k < legend_.size(); ++k) {
    const double y = y0 + 12 + row * k;
    r.line(x0 + 6, y - 4, x0 + 28, y - 4, legend_[k].color, 2, legend_[k].dashed);
    r.text(x0 + 34, y, legend_[k].name, kNumberSize, kBlack);
  }
}

void Plot::reference(double y, Rgb color, const std::string& name) {
  if (!name.empty()) legend_.push_back({name, color, true});
  if (y < y0_ || y > y1_) return;
  drawing_.line(left_, py(y), right_, py(y), color, 1.5, true);
}

void Plot::polyline(const std::vector<std::array<double, 2>>& points, Rgb color, const std::string& name) {
  if (!name.empty()) legend_.push_back({name, color, false});
  std::vector<std::array<double, 2>> pixels;
  for (const auto& p : points) pixels.push_back({px(p[0]), py(p[1])});
  drawing_.clip(left_, top_, right_ + 1, bottom_ + 1);
  drawing_.polyline(pixels, color);
  drawing_.unclip();
}

void Plot::bar(double xa, double xb, double y, Rgb color) {
  const int a = static_cast<int>(std::lround(px(xa))), b = std::max(static_cast<int>(std::lround(px(xb))) - 1, a);
  drawing_.fill_rect(a, static_cast<int>(std::lround(py(0))), b,
                     std::max(static_cast<int>(std::lround(py(y))), top_), color);
}

}  // namespace disktune::detail
