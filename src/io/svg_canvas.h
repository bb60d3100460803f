// SPDX-License-Identifier: GPL-3.0-or-later
// What every SVG picture of a packing's frame shares (internal): the page, the map from
// domain to pixels (y up in the domain, down in SVG), the clip to the frame, the
// periodic images of a shape that reach into it, and a legend under the frame.
#pragma once

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "disktune/frame.h"

namespace disktune::detail {

/// A legend row: a disk or a line sample in `color`, then `text`.
struct SvgLegend {
  std::string color, text;
  bool line = false;
};

class SvgCanvas {
 public:
  SvgCanvas(const Frame& frame, double pixels, std::vector<SvgLegend> legend = {})
      : f_(padded(frame)), scale_(pixels / f_.extent.x), w_(pixels), h_(f_.extent.y * scale_), legend_(std::move(legend)) {}

  double scale() const { return scale_; }
  Vec2 px(Vec2 p) const { return {(p.x - f_.origin.x) * scale_, h_ - (p.y - f_.origin.y) * scale_}; }

  /// The page, a white frame, and a group clipped to it; close with end().
  void begin(std::ostream& out) const {
    char buf[240];
    const double page = h_ + (legend_.empty() ? 0 : kRow * legend_.size() + 10);
    std::snprintf(buf, sizeof buf,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                  "viewBox=\"0 0 %.3f %.3f\">\n<rect width=\"%.3f\" height=\"%.3f\" fill=\"white\"/>\n"
                  "<clipPath id=\"frame\"><rect width=\"%.3f\" height=\"%.3f\"/></clipPath>\n",
                  w_, page, w_, page, w_, page, w_, h_);
    out << buf;
    std::snprintf(buf, sizeof buf,
                  "<rect width=\"%.3f\" height=\"%.3f\" fill=\"white\" stroke=\"black\"/>\n"
                  "<g clip-path=\"url(#frame)\">\n",
                  w_, h_);
    out << buf;
  }
  /// Closes the clipped group, draws the legend under the frame, closes the page.
  void end(std::ostream& out) const {
    out << "</g>\n<g font-family=\"sans-serif\" font-size=\"13\">\n";
    char buf[200];
    for (std::size_t k = 0; k < legend_.size(); ++k) {
      const double y = h_ + 8 + kRow * (k + 0.5);
      if (legend_[k].line) {
        std::snprintf(buf, sizeof buf, "<line x1=\"8\" y1=\"%.1f\" x2=\"26\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"/>\n", y, y,
                      legend_[k].color.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "<circle cx=\"17\" cy=\"%.1f\" r=\"6\" fill=\"%s\"/>\n", y, legend_[k].color.c_str());
      }
      out << buf;
      std::snprintf(buf, sizeof buf, "<text x=\"34\" y=\"%.1f\">", y + 4.5);
      out << buf << legend_[k].text << "</text>\n";
    }
    out << "</g>\n</svg>\n";
  }

  /// Calls draw(shift) for each periodic image of the box [lo, hi] that meets the frame
  /// (the shape itself only, for a frame that is not periodic).
  template <class Draw>
  void for_each_image(Vec2 lo, Vec2 hi, Draw&& draw) const {
    const int span = f_.periodic ? 1 : 0;
    for (int wy = -span; wy <= span; ++wy) {
      for (int wx = -span; wx <= span; ++wx) {
        const Vec2 s{wx * f_.extent.x, wy * f_.extent.y};
        if (hi.x + s.x < f_.origin.x || lo.x + s.x > f_.origin.x + f_.extent.x ||
            hi.y + s.y < f_.origin.y || lo.y + s.y > f_.origin.y + f_.extent.y) {
          continue;
        }
        draw(s);
      }
    }
  }

 private:
  // A bounded domain's frame is its bounding box, so disks on the boundary would be cut
  // in half: show a margin around it. A periodic frame is the whole domain.
  static Frame padded(Frame f) {
    if (f.periodic) return f;
    const double m = 0.02 * std::max(f.extent.x, f.extent.y);
    return {f.origin - Vec2{m, m}, f.extent + Vec2{2 * m, 2 * m}, false};
  }

  static constexpr double kRow = 20;
  Frame f_;
  double scale_, w_, h_;
  std::vector<SvgLegend> legend_;
};

}  // namespace disktune::detail
