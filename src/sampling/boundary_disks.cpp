// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary disks: 1D maximal sampling of a planar domain's boundary segments, and
// finding the boundary disks of a packing read back from a file.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "disktune/boundary.h"
#include "curve_layout.h"
#include "disktune/errors.h"
#include "disktune/tolerance.h"
#include "disktune/voids.h"

namespace disktune {

namespace {

// Each segment's uncovered stretches laid out evenly (curve_layout.h), from the disk that
// ends each: the segment's own corner disk, else a new disk at the stretch's end, just
// outside the disk of another segment that covers up to there (near a sharp corner).
void lay_out_segments(Packing& packing, const PlanarDomain& domain) {
  for (const BoundarySegment& s : domain.segments()) {
    const auto at = [&](double t) { return s.a + (s.b - s.a) * t; };
    const auto radius = [&](Vec2 x) { return packing.radius_at(x); };
    const auto place = [&](Vec2 x) { return packing.covered(x) ? kNoDisk : packing.insert(x, radius(x), kFixed); };
    const auto remove = [&](DiskId id) { packing.remove(id); };
    // Is the end t of a stretch where corner c's disk ends (not beyond it)?
    const auto ends_at = [&](double t, Vec2 c) { return distance(at(t), c) <= radius(c) * (1 + 4 * kRelTol); };
    // A new end disk just inside the stretch, clear of the covering disk's tolerance.
    const double inset = 4 * kRelTol * packing.max_radius() / distance(s.a, s.b);
    for (const auto& g : uncovered_on_segment(packing, s.a, s.b, true)) {
      const bool from_corner = ends_at(g[0], s.a), to_corner = ends_at(g[1], s.b);
      const double from = from_corner ? 0.0 : g[0] + inset, to = to_corner ? 1.0 : g[1] - inset;
      if (from < to) detail::lay_out_evenly(from, to, !from_corner, !to_corner, 0, 8, at, radius, place, remove);
    }
  }
}

}  // namespace

void fill_boundary_voids(Packing& packing, const PlanarDomain& domain, Rng& rng) {
  std::vector<BoundarySegment> segments = domain.segments();
  for (std::size_t i = segments.size(); i > 1; --i) {
    std::swap(segments[i - 1], segments[uniform_index(rng, i)]);
  }
  for (const BoundarySegment& s : segments) {
    const double len = distance(s.a, s.b);
    std::vector<std::array<double, 2>> gaps = uncovered_on_segment(packing, s.a, s.b, true);
    while (!gaps.empty()) {
      double total = 0;
      for (const auto& g : gaps) total += g[1] - g[0];
      // A uniform point of the uncovered part: walk the gaps to the drawn length.
      double u = uniform01(rng) * total, t = gaps.back()[1];
      for (const auto& g : gaps) {
        if (u <= g[1] - g[0]) {
          t = g[0] + u;
          break;
        }
        u -= g[1] - g[0];
      }
      const Vec2 x = s.a + (s.b - s.a) * t;
      const double r = packing.radius_at(x);
      packing.insert(x, r, kFixed);
      // The new disk covers [t - r, t + r] of this segment (in parameter units).
      const double half = r * (1 + kRelTol) / len;
      std::vector<std::array<double, 2>> left;
      for (const auto& g : gaps) {
        if (g[0] < t - half) left.push_back({g[0], std::min(g[1], t - half)});
        if (g[1] > t + half) left.push_back({std::max(g[0], t + half), g[1]});
      }
      gaps.swap(left);
    }
  }
}

void sample_boundary(Packing& packing, const PlanarDomain& domain, Rng& rng) {
  // A disk on every corner; with one radius validate_radius has checked they are r
  // apart, with a sizing no corner may lie in another corner's disk.
  for (const auto& loop : domain.loops()) {
    for (const Vec2 corner : loop) {
      const double r = packing.radius_at(corner);
      packing.for_each_near(corner, packing.max_radius(), [&](const Neighbor& n) {
        if (is_conflict(n.d2, std::max(r, n.radius))) {
          std::ostringstream msg;
          msg << "the domain's corners (" << corner.x << ", " << corner.y << ") and (" << n.image.x
              << ", " << n.image.y << ") are " << std::sqrt(n.d2) << " apart, closer than their "
              << "radii " << r << " and " << n.radius << ": each corner holds a disk; use smaller radii there";
          throw InvalidInput(msg.str());
        }
      });
      packing.insert(corner, r, kFixed);
    }
  }
  lay_out_segments(packing, domain);
  fill_boundary_voids(packing, domain, rng);
}

BoundaryLoops boundary_loops(Packing& packing, const PlanarDomain& domain) {
  const double r = packing.max_radius();
  const double tol = 1e-9 * r;
  for (const DiskId id : packing.ids()) packing.set_flags(id, packing.flags(id) & ~kFixed);
  BoundaryLoops loops(domain.loops().size());
  for (const BoundarySegment& s : domain.segments()) {
    const Vec2 d = s.b - s.a;
    const double len = norm(d);
    // The disks on the segment, by their parameter along it; its end is the next
    // segment's start (a corner), listed there.
    std::vector<std::pair<double, DiskId>> on;
    const int pieces = std::max(1, static_cast<int>(std::ceil(len / r)));
    for (int k = 0; k < pieces; ++k) {
      packing.for_each_near(s.a + d * ((k + 0.5) / pieces), 0.5 * len / pieces + tol, [&](const Neighbor& n) {
        const double t = dot(n.image - s.a, d) / (len * len);
        if (t < 0 || t * len >= len - tol || (packing.flags(n.id) & kFixed)) return;
        if (distance(n.image, s.a + d * t) <= tol) on.push_back({t, n.id});
      });
    }
    std::sort(on.begin(), on.end());
    on.erase(std::unique(on.begin(), on.end()), on.end());  // found by two pieces' queries
    if (on.empty() || on.front().first * len > tol) {
      std::ostringstream msg;
      msg << "no disk on corner " << s.index << " of boundary loop " << s.loop << " at (" << s.a.x
          << ", " << s.a.y << "): a packing of a planar domain has a disk on every corner; "
          << "start from a sample of the domain";
      throw InvalidInput(msg.str(), InvalidInput::Remedy::sample);
    }
    for (const auto& [t, id] : on) {
      packing.set_flags(id, packing.flags(id) | kFixed);
      loops[s.loop].push_back(id);
    }
  }
  return loops;
}

}  // namespace disktune
