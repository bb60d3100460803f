// SPDX-License-Identifier: GPL-3.0-or-later
// What a sizing function does over a domain, found by sampling it on a regular lattice:
// its range, its gradation (the Lipschitz constant that bounds mesh angles, see
// docs/sizing.md) and the disk count a relative density asks for.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "../domain/point_text.h"
#include "../domain/radius_limits.h"
#include "disktune/errors.h"
#include "disktune/sizing.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A lattice of about `samples` nodes over the frame with near-square cells. A bounded
// frame puts nodes on its edges (where boundary grading has its extremes); a periodic
// one spaces them evenly around the torus, so the last column neighbours the first.
struct Lattice {
  long long nx = 0, ny = 0;
  Vec2 origin{0, 0}, extent{1, 1};
  bool periodic = false;

  Lattice(const Frame& frame, int samples)
      : origin(frame.origin), extent(frame.extent), periodic(frame.periodic) {
    const double w = extent.x, h = extent.y;
    if (!std::isfinite(w) || !std::isfinite(h) || !(w > 0) || !(h > 0) ||
        !std::isfinite(origin.x) || !std::isfinite(origin.y)) {
      throw InvalidInput("cannot sample a sizing over a frame of extent " +
                         detail::point_text(extent) + " at " + detail::point_text(origin) +
                         ": the frame must be finite with positive width and height");
    }
    if (samples < 4) {
      throw InvalidInput("sampling a sizing needs at least 4 points, got samples = " +
                         std::to_string(samples));
    }
    // At least 4 nodes a side even for a thin frame (a strip 1e-5 wide), so that its
    // inside is sampled and not only its two edges; a very thin frame gets more nodes.
    const long long most = 4LL * samples;
    nx = std::clamp<long long>(std::llround(std::sqrt(samples * (w / h))), 4, most);
    ny = std::clamp<long long>(std::llround(static_cast<double>(samples) / static_cast<double>(nx)), 4, most);
  }

  // Steps between nodes along each axis.
  long long steps_x() const { return periodic ? nx : nx - 1; }
  long long steps_y() const { return periodic ? ny : ny - 1; }
  double hx() const { return extent.x / static_cast<double>(steps_x()); }
  double hy() const { return extent.y / static_cast<double>(steps_y()); }

  // Node (i, j), or with `half` the center of the cell above and right of it. Computed
  // by division so that a bounded frame's last node is exactly on its edge.
  Vec2 point(long long i, long long j, bool half = false) const {
    const double s = half ? 0.5 : 0.0;
    return {origin.x + extent.x * ((static_cast<double>(i) + s) / static_cast<double>(steps_x())),
            origin.y + extent.y * ((static_cast<double>(j) + s) / static_cast<double>(steps_y()))};
  }
};

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// r at p, refused unless finite and positive: every use of r divides by it or packs
// disks of that size.
double radius_at(const Sizing& sizing, Vec2 p) {
  const double r = sizing(p);
  if (!std::isfinite(r) || !(r > 0)) {
    throw InvalidInput("the sizing \"" + sizing.description() + "\" gives r = " +
                       short_number(r) + " at " + detail::point_text(p) +
                       "; r must be finite and positive everywhere in the domain (e.g. add a "
                       "positive floor with max(..., 0.001))");
  }
  return r;
}

}  // namespace

SizingStats measure_sizing(const Sizing& sizing, const Frame& frame, const PlanarDomain* domain,
                           int samples) {
  const Lattice lat(frame, samples);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> r(static_cast<std::size_t>(lat.nx * lat.ny), nan);  // NaN: outside
  SizingStats stats;
  stats.min = std::numeric_limits<double>::infinity();
  stats.max = 0;
  long long inside = 0;
  for (long long j = 0; j < lat.ny; ++j) {
    for (long long i = 0; i < lat.nx; ++i) {
      const Vec2 p = lat.point(i, j);
      if (domain && !domain->contains(p)) continue;
      const double v = radius_at(sizing, p);
      r[static_cast<std::size_t>(j * lat.nx + i)] = v;
      stats.min = std::min(stats.min, v);
      stats.max = std::max(stats.max, v);
      ++inside;
    }
  }
  if (inside == 0) {
    throw InvalidInput("no sample point of the frame at " + detail::point_text(frame.origin) +
                       " lies inside the domain, so the sizing \"" + sizing.description() +
                       "\" cannot be measured; pass the domain's own frame");
  }
  // Right, up and both diagonals: each neighbouring pair once (twice across a seam of
  // only two columns, which does no harm).
  const long long offsets[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  for (const auto& o : offsets) {
    const double dist = std::hypot(static_cast<double>(o[0]) * lat.hx(),
                                   static_cast<double>(o[1]) * lat.hy());
    for (long long j = 0; j < lat.ny; ++j) {
      for (long long i = 0; i < lat.nx; ++i) {
        long long ni = i + o[0], nj = j + o[1];
        if (lat.periodic) {
          ni = (ni + lat.nx) % lat.nx;
          nj = nj % lat.ny;
        } else if (ni < 0 || ni >= lat.nx || nj >= lat.ny) {
          continue;
        }
        const double a = r[static_cast<std::size_t>(j * lat.nx + i)];
        const double b = r[static_cast<std::size_t>(nj * lat.nx + ni)];
        if (std::isnan(a) || std::isnan(b)) continue;
        stats.lipschitz = std::max(stats.lipschitz, std::abs(a - b) / dist);
      }
    }
  }
  // Between nodes r can rise above the largest sample by about L times the distance to
  // the nearest node; 5 % at least, as L is only estimated.
  stats.upper = std::max(stats.max * 1.05, stats.max + stats.lipschitz * std::hypot(lat.hx(), lat.hy()));
  return stats;
}

void check_gradation(const SizingStats& stats, double limit) {
  if (!std::isfinite(limit) || !(limit > 0)) {
    throw InvalidInput("the gradation limit " + short_number(limit) + " must be positive");
  }
  const double L = stats.lipschitz;
  if (!(L >= limit)) return;
  std::string why;
  if (L >= 0.5) {
    why = "with L >= 1/2 a maximal packing has no angle bound (sin of the smallest Delaunay "
          "angle >= (1 - 2L) / (2 (1 + L)), which is not positive)";
  } else {
    const double degrees = angle_bound_degrees(L);
    why = "the smallest Delaunay angle is then only guaranteed to be " + short_number(degrees) +
          " degrees (sin >= (1 - 2L) / (2 (1 + L)))";
  }
  throw InvalidInput("the sizing's gradation L = " + short_number(L) +
                     " (largest |r(a)-r(b)|/|a-b| found) is at or above " + short_number(limit) +
                     ": " + why +
                     "; make r vary more slowly, e.g. smaller coefficients of x and y in an "
                     "expression or a smaller G in boundary:RMIN,RMAX,G; on a periodic box r "
                     "must also match across the box's edges (see docs/sizing.md)");
}

namespace {

// Calls f(center, 4 / (pi r^2)) for every cell between the lattice's nodes whose center
// lies in the domain (the midpoint rule of the density integrals below); returns how
// many there were, and throws when there were none.
template <class F>
long long for_each_cell_density(const Lattice& lat, const Sizing& sizing, const Frame& frame,
                                const PlanarDomain* domain, F&& f) {
  long long inside = 0;
  for (long long j = 0; j < lat.steps_y(); ++j) {
    for (long long i = 0; i < lat.steps_x(); ++i) {
      const Vec2 c = lat.point(i, j, true);
      if (domain && !domain->contains(c)) continue;
      const double r = radius_at(sizing, c);
      f(c, 4 / (kPi * r * r));
      ++inside;
    }
  }
  if (inside == 0) {
    throw InvalidInput("no sample point of the frame at " + detail::point_text(frame.origin) +
                       " lies inside the domain, so the density integral of the sizing \"" +
                       sizing.description() + "\" cannot be computed; pass the domain's own frame");
  }
  return inside;
}

}  // namespace

double density_integral(const Sizing& sizing, const Frame& frame, const PlanarDomain* domain,
                        int samples) {
  const Lattice lat(frame, samples);
  // Midpoint rule over the cells between the nodes measure_sizing samples. Cells whose
  // center is outside the domain are left out; the mean over the others is scaled by
  // the domain's exact area, so a constant r gives A / (pi r^2 / 4) exactly.
  double sum = 0;
  const long long inside =
      for_each_cell_density(lat, sizing, frame, domain, [&](Vec2, double density) { sum += density; });
  const double area = domain ? domain->area() : frame.extent.x * frame.extent.y;
  return area * sum / static_cast<double>(inside);
}

double densest_cell_integral(const Sizing& sizing, const Frame& frame, const PlanarDomain* domain,
                             double cell, int samples) {
  if (!std::isfinite(cell) || !(cell > 0)) {
    throw InvalidInput("the cell size " + short_number(cell) + " must be finite and positive");
  }
  const Lattice lat(frame, samples);
  // The cells as SpatialGrid lays them out: a whole number per side, at most 32768.
  auto cells = [&](double len) { return static_cast<long long>(std::clamp(std::ceil(len / cell), 1.0, 32768.0)); };
  const long long nx = cells(frame.extent.x), ny = cells(frame.extent.y);
  const double hx = frame.extent.x / static_cast<double>(nx), hy = frame.extent.y / static_cast<double>(ny);
  if (nx * ny >= lat.steps_x() * lat.steps_y()) {
    // Cells no larger than the lattice's: the density is about constant over one.
    double densest = 0;
    for_each_cell_density(lat, sizing, frame, domain, [&](Vec2, double d) { densest = std::max(densest, d); });
    return densest * hx * hy;
  }
  // Each lattice cell adds its share to the grid cell holding its center.
  std::vector<double> sum(static_cast<std::size_t>(nx * ny), 0.0);
  const double share = lat.hx() * lat.hy();
  for_each_cell_density(lat, sizing, frame, domain, [&](Vec2 c, double d) {
    const long long i = std::clamp(static_cast<long long>((c.x - frame.origin.x) / hx), 0LL, nx - 1);
    const long long j = std::clamp(static_cast<long long>((c.y - frame.origin.y) / hy), 0LL, ny - 1);
    sum[static_cast<std::size_t>(j * nx + i)] += d * share;
  });
  return *std::max_element(sum.begin(), sum.end());
}

double angle_bound_degrees(double lipschitz) {
  const double L = lipschitz;
  return L >= 0.5 ? 0.0 : std::asin((1 - 2 * L) / (2 * (1 + L))) * 180 / kPi;
}

std::size_t count_for_density(double eta, const Sizing& sizing, const Frame& frame,
                              const PlanarDomain* domain, int samples) {
  if (!std::isfinite(eta) || !(eta > 0)) {
    throw InvalidInput("the relative density eta = " + short_number(eta) +
                       " must be finite and positive (maximal packings have eta about 0.5 to 0.9)");
  }
  const double count = eta * density_integral(sizing, frame, domain, samples);
  if (!(count >= 0.5)) {
    throw InvalidInput("relative density eta = " + short_number(eta) + " with the sizing \"" +
                       sizing.description() +
                       "\" asks for no disk at all; raise eta or make r smaller");
  }
  if (!(count <= detail::kMaxDisks)) {
    throw InvalidInput("relative density eta = " + short_number(eta) + " with the sizing \"" +
                       sizing.description() + "\" asks for " + short_number(count) +
                       " disks, more than the 4e9 a packing can number; make r larger");
  }
  return static_cast<std::size_t>(std::llround(count));
}

}  // namespace disktune
