// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdio>
#include <vector>

#include "disktune/io.h"
#include "svg_canvas.h"

namespace disktune {

void write_packing_svg(const std::string& path, const Packing& packing, const SvgStyle& style) {
  bool fixed = false, frozen = false;
  for (const DiskId id : packing.ids()) fixed |= (packing.flags(id) & kFixed) != 0, frozen |= (packing.flags(id) & kFrozen) != 0;
  std::vector<detail::SvgLegend> legend{{"#4c4c4c", "a disk, drawn at half its radius: no two overlap, so no two centers are closer than r"}};
  if (fixed) legend.push_back({"#d62728", "a disk held on the boundary"});
  if (frozen) legend.push_back({"#1f77b4", "a frozen disk (a crystal's)"});
  const detail::SvgCanvas canvas(packing.frame(), style.pixels, legend);
  write_file_atomically(path, [&](std::ostream& out) {
    canvas.begin(out);
    out << "<g stroke=\"none\">\n";
    char buf[160];
    for (DiskId id = 0; id < packing.id_bound(); ++id) {
      if (!packing.alive(id)) continue;
      const double half = packing.radius(id) / 2;
      const std::uint8_t fl = packing.flags(id);
      const char* color = (fl & kFixed) ? "#d62728" : (fl & kFrozen) ? "#1f77b4" : "#4c4c4c";
      const Vec2 c = packing.center(id);
      canvas.for_each_image(c - Vec2{half, half}, c + Vec2{half, half}, [&](Vec2 s) {
        const Vec2 q = canvas.px(c + s);
        std::snprintf(buf, sizeof buf, "<circle cx=\"%.3f\" cy=\"%.3f\" r=\"%.3f\" fill=\"%s\"/>\n",
                      q.x, q.y, half * canvas.scale(), color);
        out << buf;
      });
    }
    out << "</g>\n";
    canvas.end(out);
  });
}

}  // namespace disktune
