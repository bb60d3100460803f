// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cstdio>

#include "disktune/io.h"
#include "disktune/mesh_io.h"
#include "svg_canvas.h"

namespace disktune {

void write_mesh_svg(const std::string& path, const TriangleMesh& mesh, const Packing& packing,
                    const MeshSvgStyle& style) {
  const detail::SvgCanvas canvas(packing.frame(), style.pixels);
  write_file_atomically(path, [&](std::ostream& out) {
    canvas.begin(out);
    char buf[160];
    out << "<g fill=\"#d0d0d0\" stroke=\"none\">\n";
    for (const DiskId id : packing.ids()) {
      const double half = packing.radius(id) / 2;
      const Vec2 c = packing.center(id);
      canvas.for_each_image(c - Vec2{half, half}, c + Vec2{half, half}, [&](Vec2 s) {
        const Vec2 q = canvas.px(c + s);
        std::snprintf(buf, sizeof buf, "<circle cx=\"%.3f\" cy=\"%.3f\" r=\"%.3f\"/>\n", q.x, q.y,
                      half * canvas.scale());
        out << buf;
      });
    }
    out << "</g>\n<path fill=\"none\" stroke=\"#1f4e9c\" stroke-width=\"0.6\" d=\"";
    for (const auto& e : unique_edges(mesh)) {
      const Vec2 a = mesh.vertices[e[0]], b = mesh.vertices[e[1]];
      const Vec2 lo{std::min(a.x, b.x), std::min(a.y, b.y)};
      const Vec2 hi{std::max(a.x, b.x), std::max(a.y, b.y)};
      canvas.for_each_image(lo, hi, [&](Vec2 s) {
        const Vec2 p = canvas.px(a + s), q = canvas.px(b + s);
        std::snprintf(buf, sizeof buf, "M%.2f %.2fL%.2f %.2f", p.x, p.y, q.x, q.y);
        out << buf;
      });
    }
    out << "\"/>\n";
    canvas.end(out);
  });
}

}  // namespace disktune
