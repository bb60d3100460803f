// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling on a surface: the open boundary curves first (1D darts
// into the uncovered parts of the boundary edges, as fixed disks), then darts over the
// surface by area, then every remaining void filled at its void points, each new disk
// queuing the void points around it, until no void point is left.
#include <algorithm>

#include "disktune/errors.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_voids.h"
#include "disktune/tolerance.h"
#include "../voids/final_check.h"

namespace disktune {
namespace {

void sample_boundary(SurfacePacking& packing, Rng& rng) {
  const SurfaceDomain& d = packing.domain();
  if (d.is_closed()) return;
  // The gaps of each boundary edge, in loop and edge order, measured once; a new disk
  // changes only those of the edges it reaches.
  struct Edge {
    std::size_t loop, edge;
    Vec3 a, b;
    std::vector<BoundaryGap> gaps;
  };
  std::vector<Edge> edges;
  for (std::size_t l = 0; l < d.boundary_loops().size(); ++l) {
    const auto& loop = d.boundary_loops()[l];
    for (std::size_t e = 0; e < loop.size(); ++e) {
      edges.push_back({l, e, d.vertices()[loop[e]], d.vertices()[loop[(e + 1) % loop.size()]], {}});
      uncovered_on_boundary_edge(packing, l, e, true, edges.back().gaps);
    }
  }
  std::vector<double> cumulative;
  std::vector<const BoundaryGap*> gaps;
  for (;;) {
    // A dart uniform over the uncovered length.
    cumulative.clear();
    gaps.clear();
    double total = 0;
    for (const Edge& e : edges) {
      for (const BoundaryGap& g : e.gaps) {
        total += (g.t1 - g.t0) * norm(e.b - e.a);
        cumulative.push_back(total);
        gaps.push_back(&g);
      }
    }
    if (gaps.empty()) return;
    const std::size_t k = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), uniform01(rng) * total) - cumulative.begin(),
        gaps.size() - 1);
    const BoundaryGap g = *gaps[k];
    const DiskId id =
        packing.insert(packing.index().on_boundary(g.loop, g.edge, g.t0 + (g.t1 - g.t0) * uniform01(rng)), kFixed);
    // The new disk covers one interval of each edge it reaches: cut it out of the gaps
    // there (measuring such an edge again would cost its length over r per disk).
    for (Edge& e : edges) {
      const auto in = segment_in_ball(e.a, e.b, packing.center(id), packing.radius(id) * (1 + kRelTol));
      if (!in) continue;
      std::vector<BoundaryGap> left;
      for (const BoundaryGap& g : e.gaps) {
        if (g.t1 <= (*in)[0] || g.t0 >= (*in)[1]) {
          left.push_back(g);
          continue;
        }
        if (g.t0 < (*in)[0]) left.push_back({g.loop, g.edge, g.t0, (*in)[0]});
        if ((*in)[1] < g.t1) left.push_back({g.loop, g.edge, (*in)[1], g.t1});
      }
      e.gaps.swap(left);
    }
  }
}

}  // namespace

SurfacePacking sample_mps(std::shared_ptr<const SurfaceDomain> domain, const SurfaceSizing& sizing, Rng& rng) {
  SurfacePacking packing(std::move(domain), sizing);
  sample_boundary(packing, rng);
  // Darts: about twice the count at area fraction 1 (an MPS reaches about half of it).
  const std::size_t darts = static_cast<std::size_t>(2 * density_unit(packing)) + 16;
  for (std::size_t k = 0; k < darts; ++k) {
    const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
    const SurfacePoint q = packing.index().point_by_area(u1, u2, u3);
    if (!packing.covered(q.p)) packing.insert(q);
  }
  // Fill what the darts missed, in random order.
  std::vector<SurfaceVoidPoint> work;
  for (std::size_t t = 0; t < packing.domain().triangles().size(); ++t) void_points_in_triangle(packing, t, {}, work);
  for (std::size_t i = work.size(); i > 1; --i) std::swap(work[i - 1], work[uniform_index(rng, i)]);
  while (!work.empty()) {
    const SurfaceVoidPoint v = work.back();
    work.pop_back();
    // Strictly inside a disk placed since: covered. A point only on such a disk's circle
    // may still open a wedge of void (surface_voids.h), so it gets a disk too.
    if (packing.conflicts(v.at.p)) continue;
    const DiskId id = packing.insert(v.at);
    const std::size_t first = work.size();
    void_points_near(packing, v.at.p, packing.radius(id) * (1 + 1e-6), {}, work);
    for (std::size_t i = work.size(); i > first + 1; --i) std::swap(work[i - 1], work[first + uniform_index(rng, i - first)]);
  }
  detail::check_sample(packing);
  return packing;
}

}  // namespace disktune
