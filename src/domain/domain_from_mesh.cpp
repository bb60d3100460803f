// SPDX-License-Identifier: GPL-3.0-or-later
// A planar domain from a flat triangle mesh: its boundary edges (those of one triangle
// only) chained into loops, the largest one outer. And the reader that picks a format.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "../io/file_extension.h"
#include "../io/polygon_soup.h"
#include "disktune/errors.h"
#include "half_edges.h"
#include "disktune/planar_domain.h"
#include "loop_validation.h"
#include "point_text.h"

namespace disktune {
namespace {

using detail::point_text;

std::string vertex_text(const std::vector<Vec2>& points, std::size_t v) {
  return "vertex " + std::to_string(v) + ' ' + point_text(points[v]);
}

// Triangles turned counterclockwise, after checking each names three distinct vertices
// and has an area.
std::vector<std::array<std::size_t, 3>> oriented_triangles(
    const std::vector<Vec2>& points, const std::vector<std::array<std::size_t, 3>>& triangles) {
  std::vector<std::array<std::size_t, 3>> out = triangles;
  for (std::size_t t = 0; t < out.size(); ++t) {
    auto& tri = out[t];
    for (const std::size_t v : tri) {
      if (v >= points.size()) {
        throw InvalidInput("triangle " + std::to_string(t) + " names vertex " + std::to_string(v) +
                           ", but there are only " + std::to_string(points.size()) + " vertices");
      }
    }
    const double twice_area =
        cross(points[tri[1]] - points[tri[0]], points[tri[2]] - points[tri[0]]);
    if (twice_area == 0) {
      throw InvalidInput("triangle " + std::to_string(t) + " (" + vertex_text(points, tri[0]) +
                         ", " + vertex_text(points, tri[1]) + ", " + vertex_text(points, tri[2]) +
                         ") has zero area; remove degenerate triangles");
    }
    if (twice_area < 0) std::swap(tri[1], tri[2]);
  }
  return out;
}

// With every triangle counterclockwise, an inner edge is used once each way and a
// boundary edge once, with the domain on its left.
std::vector<std::size_t> boundary_successors(const std::vector<Vec2>& points,
                                             const std::vector<std::array<std::size_t, 3>>& tris) {
  const std::vector<detail::HalfEdge> edges = detail::sorted_half_edges(tris);
  const std::size_t none = points.size();
  std::vector<std::size_t> next(points.size(), none);
  detail::for_each_edge(edges, [&](std::size_t g, std::size_t end) {
    const detail::HalfEdge& e = edges[g];
    const std::string between =
        "the edge between " + vertex_text(points, e.lo) + " and " + vertex_text(points, e.hi);
    if (end - g > 2) {
      throw InvalidInput(
          between + " belongs to " + std::to_string(end - g) + " triangles (triangles " +
          std::to_string(edges[g].tri) + ", " + std::to_string(edges[g + 1].tri) + ", " +
          std::to_string(edges[g + 2].tri) + "); a flat mesh has at most two per edge");
    }
    if (end - g == 2 && e.forward == edges[g + 1].forward) {
      throw InvalidInput("triangles " + std::to_string(e.tri) + " and " +
                         std::to_string(edges[g + 1].tri) + " lie on the same side of " + between +
                         ", so they overlap; the mesh must not fold over itself");
    }
    if (end - g == 1) {
      const std::size_t from = e.forward ? e.lo : e.hi, to = e.forward ? e.hi : e.lo;
      if (next[from] != none) {
        throw InvalidInput(vertex_text(points, from) + " starts two boundary edges (to vertices " +
                           std::to_string(next[from]) + " and " + std::to_string(to) +
                           "): two boundary loops touch there; separate them");
      }
      next[from] = to;
    }
  });
  return next;
}

std::vector<std::vector<Vec2>> chain(const std::vector<Vec2>& points,
                                     const std::vector<std::size_t>& next) {
  const std::size_t none = points.size();
  std::vector<bool> seen(points.size(), false);
  std::vector<std::vector<Vec2>> loops;
  for (std::size_t first = 0; first < points.size(); ++first) {
    if (next[first] == none || seen[first]) continue;
    std::vector<Vec2> loop;
    std::size_t v = first;
    for (; !seen[v]; v = next[v]) {
      if (next[v] == none) {
        throw InvalidInput("the boundary stops at " + vertex_text(points, v) +
                           ": no boundary edge leaves it; the mesh is not a flat surface there");
      }
      seen[v] = true;
      loop.push_back(points[v]);
    }
    // Ending anywhere but at the start means a second boundary edge arrives there.
    if (v != first) {
      throw InvalidInput("two boundary edges end at " + vertex_text(points, v) +
                         ": the mesh's boundary loops touch there; separate them");
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

PlanarDomain read_mesh_domain(const std::string& path) {
  const detail::PolygonSoup soup = detail::read_polygon_soup(path);
  if (soup.polygons.empty()) throw InvalidInput(path + ": the mesh has no faces");
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const auto& poly = soup.polygons[f];
    if (poly.size() != 3) {
      throw InvalidInput(path + ": face " + std::to_string(f) + " has " +
                         std::to_string(poly.size()) +
                         " vertices; only triangles are supported, triangulate the mesh first");
    }
    triangles.push_back({poly[0], poly[1], poly[2]});
  }
  // Flat: z equal to vertex 0's, up to a relative 1e-9 of the extent in x and y.
  std::vector<Vec2> points;
  double extent = 0;
  for (const auto& p : soup.points) {
    points.push_back({p[0], p[1]});
    extent =
        std::max({extent, std::abs(p[0] - soup.points[0][0]), std::abs(p[1] - soup.points[0][1])});
  }
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (!(std::abs(soup.points[v][2] - soup.points[0][2]) <= 1e-9 * extent)) {
      std::ostringstream msg;
      msg << path << ": not planar: vertex " << v << " has z=" << soup.points[v][2]
          << " but vertex 0 has z=" << soup.points[0][2]
          << "; a planar domain's mesh must lie in a plane z = constant";
      throw InvalidInput(msg.str());
    }
  }
  try {
    return planar_domain_from_triangles(points, triangles);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
}

}  // namespace

PlanarDomain planar_domain_from_triangles(
    const std::vector<Vec2>& points, const std::vector<std::array<std::size_t, 3>>& triangles) {
  if (triangles.empty()) throw InvalidInput("the triangle mesh has no triangles");
  const auto tris = oriented_triangles(points, triangles);
  std::vector<std::vector<Vec2>> loops = chain(points, boundary_successors(points, tris));
  // The outer loop has the largest area; holes keep the order of their first vertex.
  std::vector<double> area;
  for (const auto& loop : loops) area.push_back(std::abs(detail::twice_signed_area(loop)));
  const auto outer = std::max_element(area.begin(), area.end()) - area.begin();
  std::rotate(loops.begin(), loops.begin() + outer, loops.begin() + outer + 1);
  std::vector<Vec2> outer_loop = std::move(loops[0]);
  loops.erase(loops.begin());
  try {
    return PlanarDomain(std::move(outer_loop), std::move(loops));
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string("the boundary of the triangle mesh is not a valid domain: ") +
                       e.what());
  }
}

PlanarDomain read_planar_domain(const std::string& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".poly") return read_poly(path);
  if (ext == ".off" || ext == ".obj") return read_mesh_domain(path);
  throw InvalidInput("cannot read a planar domain from " + path + ": unknown extension '" + ext +
                     "'; use .poly (Triangle), or .off or .obj (a flat triangle mesh)");
}

}  // namespace disktune
