// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cstdio>

#include "disktune/io.h"
#include "disktune/mesh_io.h"
#include "svg_canvas.h"

namespace disktune {
namespace {

using Edges = std::vector<std::array<std::uint32_t, 2>>;

/// One picture for both mesh kinds: the disks at half radius, then each edge
/// vertices[a]..vertices[b] once, every periodic image that reaches into the frame.
void write_edges_svg(const std::string& path, const std::vector<Vec2>& vertices, const Edges& edges,
                     const Packing& packing, const MeshSvgStyle& style) {
  bool fixed = false;
  for (const DiskId id : packing.ids()) fixed |= (packing.flags(id) & kFixed) != 0;
  std::vector<detail::SvgLegend> legend{{"#d0d0d0", "a disk at half its radius (a mesh vertex)"}};
  if (fixed) legend.push_back({"#f0a0a0", "a disk held on the boundary"});
  legend.push_back({"#1f4e9c", "an edge of the Delaunay mesh", true});
  const detail::SvgCanvas canvas(packing.frame(), style.pixels, legend);
  write_file_atomically(path, [&](std::ostream& out) {
    canvas.begin(out);
    char buf[160];
    out << "<g fill=\"#d0d0d0\" stroke=\"none\">\n";
    for (const DiskId id : packing.ids()) {
      const double half = packing.radius(id) / 2;
      const Vec2 c = packing.center(id);
      // Light, so the edges stay readable over them.
      const char* fill = (packing.flags(id) & kFixed) ? " fill=\"#f0a0a0\"" : "";
      canvas.for_each_image(c - Vec2{half, half}, c + Vec2{half, half}, [&](Vec2 s) {
        const Vec2 q = canvas.px(c + s);
        std::snprintf(buf, sizeof buf, "<circle cx=\"%.3f\" cy=\"%.3f\" r=\"%.3f\"%s/>\n", q.x, q.y,
                      half * canvas.scale(), fill);
        out << buf;
      });
    }
    out << "</g>\n<path fill=\"none\" stroke=\"#1f4e9c\" stroke-width=\"0.6\" d=\"";
    for (const auto& e : edges) {
      const Vec2 a = vertices[e[0]], b = vertices[e[1]];
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

/// Each edge of a planar mesh once (interior edges are shared by two triangles,
/// boundary edges belong to one).
Edges planar_edges(const PlanarMesh& mesh) {
  Edges edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[k], v = t[(k + 1) % 3];
      edges.push_back({std::min(u, v), std::max(u, v)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace

void write_mesh_svg(const std::string& path, const TriangleMesh& mesh, const Packing& packing,
                    const MeshSvgStyle& style) {
  write_edges_svg(path, mesh.vertices, unique_edges(mesh), packing, style);
}

void write_mesh_svg(const std::string& path, const PlanarMesh& mesh, const Packing& packing,
                    const MeshSvgStyle& style) {
  write_edges_svg(path, mesh.vertices, planar_edges(mesh), packing, style);
}

}  // namespace disktune
