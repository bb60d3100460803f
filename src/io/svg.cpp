// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>

#include "disktune/io.h"

namespace disktune {

void write_packing_svg(const std::string& path, const Packing& packing, const SvgStyle& style) {
  const Frame& f = packing.frame();
  const double scale = style.pixels / f.extent.x;
  const double w = style.pixels, h = f.extent.y * scale;
  write_file_atomically(path, [&](std::ostream& out) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                  "viewBox=\"0 0 %.3f %.3f\">\n",
                  w, h, w, h);
    out << buf;
    out << "<clipPath id=\"frame\"><rect width=\"" << w << "\" height=\"" << h
        << "\"/></clipPath>\n<rect width=\"" << w << "\" height=\"" << h
        << "\" fill=\"white\" stroke=\"black\"/>\n<g clip-path=\"url(#frame)\" stroke=\"none\">\n";
    // y grows upwards in the domain and downwards in SVG.
    auto disk = [&](Vec2 c, double rad, const char* color) {
      std::snprintf(buf, sizeof buf, "<circle cx=\"%.3f\" cy=\"%.3f\" r=\"%.3f\" fill=\"%s\"/>\n",
                    (c.x - f.origin.x) * scale, h - (c.y - f.origin.y) * scale, rad * scale, color);
      out << buf;
    };
    for (DiskId id = 0; id < packing.id_bound(); ++id) {
      if (!packing.alive(id)) continue;
      const double half = packing.radius(id) / 2;
      const std::uint8_t fl = packing.flags(id);
      const char* color = (fl & kFixed) ? "#d62728" : (fl & kFrozen) ? "#1f77b4" : "#4c4c4c";
      const Vec2 c = packing.center(id);
      // Draw every image that reaches into the frame (at most 4 for a disk near a corner).
      const int span = f.periodic ? 1 : 0;
      for (int wy = -span; wy <= span; ++wy) {
        for (int wx = -span; wx <= span; ++wx) {
          const Vec2 im = c + Vec2{wx * f.extent.x, wy * f.extent.y};
          if (im.x + half < f.origin.x || im.x - half > f.origin.x + f.extent.x ||
              im.y + half < f.origin.y || im.y - half > f.origin.y + f.extent.y) {
            continue;
          }
          disk(im, half, color);
        }
      }
    }
    out << "</g>\n</svg>\n";
  });
}

}  // namespace disktune
