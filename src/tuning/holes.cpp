// SPDX-License-Identifier: GPL-3.0-or-later
#include "holes.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "../geometry/threads.h"
#include "disktune/mesh.h"

namespace disktune::detail {
namespace {

using Hole = std::pair<double, Vec2>;  // squared radius of the empty circle, its center

// Widest first; stable, so equal circles keep the order they were found in.
void sort_widest_first(std::vector<Hole>& holes, unsigned threads) {
  const auto wider = [](const Hole& a, const Hole& b) { return a.first > b.first; };
  // Two fixed halves sorted at once and merged, the first half first among equals:
  // the order one stable sort gives, on any number of threads.
  const auto middle = holes.begin() + static_cast<std::ptrdiff_t>(holes.size() / 2);
  parallel_for(2, threads, [&](std::size_t half, unsigned) {
    if (half == 0)
      std::stable_sort(holes.begin(), middle, wider);
    else
      std::stable_sort(middle, holes.end(), wider);
  });
  std::inplace_merge(holes.begin(), middle, holes.end(), wider);
}

std::vector<Vec2> centers_of(const std::vector<Hole>& holes) {
  std::vector<Vec2> out;
  out.reserve(holes.size());
  for (const Hole& h : holes) out.push_back(h.second);
  return out;
}

// A convex polygon around a disk's center (relative to it), each vertex with the disk
// whose bisector bounds the edge leaving it (kNoDisk: a side of the starting square).
struct Cell {
  std::vector<Vec2> at;
  std::vector<DiskId> edge;

  void square(double half) {
    at = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
    edge.assign(4, kNoDisk);
    reach2_ = 2 * half * half;
  }

  // Keeps the side of the bisector between the center and q (relative to the center)
  // that holds the center: x . q <= |q|^2 / 2.
  void clip(Vec2 q, DiskId by) {
    const double q2 = squared_norm(q);
    if (q2 >= 4 * reach2_) return;  // the bisector passes beyond every vertex
    const double limit = 0.5 * q2;
    const std::size_t n = at.size();
    next_at_.clear(), next_edge_.clear();
    reach2_ = 0;
    const auto keep = [&](Vec2 x, DiskId e) {
      next_at_.push_back(x), next_edge_.push_back(e);
      reach2_ = std::max(reach2_, squared_norm(x));
    };
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 a = at[k], b = at[(k + 1) % n];
      const double da = a.x * q.x + a.y * q.y - limit, db = b.x * q.x + b.y * q.y - limit;
      if (da <= 0) keep(a, edge[k]);
      if ((da <= 0) != (db <= 0)) keep(a + (b - a) * (da / (da - db)), da <= 0 ? by : edge[k]);
    }
    at.swap(next_at_), edge.swap(next_edge_);
  }

 private:
  double reach2_ = 0;  // the farthest vertex's squared distance
  std::vector<Vec2> next_at_;
  std::vector<DiskId> next_edge_;
};

}  // namespace

std::vector<Vec2> delaunay_holes_largest_first(const Packing& packing) {
  const TriangleMesh mesh = periodic_delaunay(packing);
  std::vector<Hole> holes;
  holes.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    if (!(cross(b - a, c - a) > 0)) continue;  // degenerate (never with distinct centers)
    const Vec2 o = circumcenter(a, b, c);
    holes.push_back({squared_norm(o - a), packing.frame().wrap(o)});
  }
  sort_widest_first(holes, 1);
  return centers_of(holes);
}

std::vector<Vec2> holes_largest_first(const Packing& packing, unsigned threads) {
  const double r = packing.max_radius();
  const Frame& frame = packing.frame();
  // Wider than 4 r: no disk has two images within 2 r of a center, nor the center itself.
  if (packing.sizing() || !(frame.extent.x >= 4.5 * r && frame.extent.y >= 4.5 * r))
    return delaunay_holes_largest_first(packing);
  const std::vector<DiskId> ids = packing.ids();
  struct Part {
    std::vector<Hole> holes;
    bool open = false;  // some cell reached past r: not maximal there
  };
  std::vector<Hole> holes;
  holes.reserve(2 * ids.size());
  bool open = false;
  const double far2 = (1.005 * r) * (1.005 * r);
  ordered_chunks<Part>(
      ids.size(), threads,
      [&](std::size_t from, std::size_t to, Part& part) {
        Cell cell;
        for (std::size_t k = from; k < to && !part.open; ++k) {
          const DiskId id = ids[k];
          const Vec2 c = packing.center(id);
          // In a maximal packing the cell lies within r of c, so its vertices' disks
          // lie within 2 r; a square a little wider than r keeps none of its own sides.
          // A vertex farther than 1.005 r could be cut off by a disk farther than 2.01 r,
          // not looked at: the packing is not maximal there, and the cells not enough.
          cell.square(1.01 * r);
          packing.for_each_near(c, 2.01 * r, [&](const Neighbor& n) {
            if (n.id != id) cell.clip(n.image - c, n.id);
          });
          const std::size_t m = cell.at.size();
          for (std::size_t v = 0; v < m; ++v) {
            const DiskId before = cell.edge[(v + m - 1) % m], after = cell.edge[v];
            if (before == kNoDisk || after == kNoDisk || squared_norm(cell.at[v]) > far2) {
              part.open = true;
              break;
            }
            if (id < before && id < after)
              part.holes.push_back({squared_norm(cell.at[v]), frame.wrap(c + cell.at[v])});
          }
        }
      },
      [&](const Part& part) {
        open |= part.open;
        holes.insert(holes.end(), part.holes.begin(), part.holes.end());
      });
  if (open) return delaunay_holes_largest_first(packing);
  sort_widest_first(holes, threads);
  return centers_of(holes);
}

}  // namespace disktune::detail
