// SPDX-License-Identifier: GPL-3.0-or-later
// Small features along a surface's fixed curves (issue #15, item 3): two feature curves
// close together along a face (a chamfer's two creases), a crease near an open boundary,
// two holes close together, a curve that bends back on itself. A disk on one such part
// covers the other in space, so no disk goes there and the mesh cuts across it.
//
// The parts a curve point does not "meet", as the planar feature sizing's segments
// other than its own and the next ones: at a corner, every curve that does not end
// there; inside a curve, every other curve that shares no corner with it; and stretches
// of its own curve more than twice as far along the curve as in space (a hairpin). Curves
// meeting at a corner never count against each other however sharp the corner (as a
// polygon's two segments at a vertex): refining there would not end. Distances are from
// each curve vertex to the curve edges; the closest points of two skew edges can lie
// inside both, which this reads a little long, by less than an edge's length.
#include "curve_clearance.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "box_tree.h"
#include "disktune/surface_sizing.h"
#include "disktune/vec3.h"

namespace disktune {
namespace detail {
namespace {

struct CurvePlace {
  std::size_t curve, position;
};

// Along curve c, how far a vertex at `position` is from edge m (0 on it).
double along_gap(const SurfaceCurve& c, const std::vector<double>& arc, std::size_t position, std::size_t m) {
  const double length = arc.back(), s = arc[position], from = arc[m], to = arc[m + 1];
  if (s >= from && s <= to) return 0;
  const double direct = s < from ? from - s : s - to;
  if (!c.closed) return direct;
  return std::min(direct, s < from ? s + (length - to) : (length - s) + from);
}

}  // namespace

std::vector<double> curve_clearance(const SurfaceDomain& domain, double reach) {
  const auto& curves = domain.fixed_curves();
  const auto& points = domain.vertices();
  std::vector<double> clearance(points.size(), reach);
  // Arc length at each vertex of each curve (a closed curve's last entry: its length).
  std::vector<std::vector<double>> arc(curves.size());
  std::vector<std::vector<CurvePlace>> places(points.size());
  std::vector<std::array<std::size_t, 2>> ends(curves.size());  // an open curve's corners
  std::vector<std::array<std::size_t, 2>> edges;                 // {curve, index of the edge}
  std::vector<BoxTree::Box> boxes;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const auto& v = curves[c].vertices;
    arc[c].push_back(0);
    for (std::size_t m = 0; m < curves[c].edge_count(); ++m) {
      const Vec3 a = points[v[m]], b = points[v[(m + 1) % v.size()]];
      arc[c].push_back(arc[c].back() + norm(b - a));
      edges.push_back({c, m});
      boxes.push_back(BoxTree::box_of(std::array<Vec3, 2>{a, b}));
    }
    for (std::size_t k = 0; k < v.size(); ++k) places[v[k]].push_back({c, k});
    ends[c] = {v.front(), v.back()};
  }
  const auto is_end = [&](std::size_t c, std::size_t vertex) {
    return !curves[c].closed && (ends[c][0] == vertex || ends[c][1] == vertex);
  };
  const auto share_corner = [&](std::size_t c, std::size_t o) {
    return !curves[c].closed && !curves[o].closed && (is_end(o, ends[c][0]) || is_end(o, ends[c][1]));
  };
  const BoxTree tree(boxes);
  for (std::size_t vertex = 0; vertex < points.size(); ++vertex) {
    const auto& here = places[vertex];
    if (here.empty()) continue;
    const bool corner = here.size() > 1 || is_end(here[0].curve, vertex);
    const auto meets = [&](std::size_t c, std::size_t m, double d) {
      bool on_c = false;
      for (const CurvePlace& p : here) {
        if (p.curve != c) continue;
        on_c = true;
        if (along_gap(curves[c], arc[c], p.position, m) <= 2 * d) return true;
      }
      return !on_c && !corner && share_corner(here[0].curve, c);
    };
    const Vec3 p = points[vertex];
    clearance[vertex] = tree.nearest(p, reach, [&](std::uint32_t e) {
      const auto [c, m] = edges[e];
      const auto& v = curves[c].vertices;
      const double d = distance_to_segment(p, points[v[m]], points[v[(m + 1) % v.size()]]);
      return meets(c, m, d) ? std::numeric_limits<double>::infinity() : d;
    });
  }
  return clearance;
}

}  // namespace detail

bool curves_fit(const SurfaceDomain& domain, double r) {
  const std::vector<double> clearance = detail::curve_clearance(domain, r);
  const auto& points = domain.vertices();
  for (const SurfaceCurve& c : domain.fixed_curves()) {
    const auto& v = c.vertices;
    const std::size_t n = v.size();
    // Runs of consecutive vertices closer than r to a part they do not meet; a closed
    // curve is walked from a vertex that is not (all of it counts when there is none).
    std::size_t start = 0;
    if (c.closed)
      while (start < n && clearance[v[start]] < r) ++start;
    if (start == n) start = 0;
    double run = -1;  // the length of the current run, -1 outside one
    for (std::size_t step = 0; step < n + (c.closed ? 1 : 0); ++step) {
      const std::size_t k = (start + step) % n;
      if (!(clearance[v[k]] < r)) {
        run = -1;
      } else {
        run = run < 0 ? 0 : run + norm(points[v[k]] - points[v[(k + n - 1) % n]]);
        if (run > 3 * r) return false;
      }
    }
  }
  return true;
}

}  // namespace disktune
