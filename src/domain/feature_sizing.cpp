// SPDX-License-Identifier: GPL-3.0-or-later
// Local feature size sizing for a planar domain (issue #15, item 3): the radius shrinks
// where boundary parts come close (a thin part, a hole near the boundary or another
// hole, a short segment), so that every segment has room for a disk between its corner
// disks and two parts never face each other closer than 2.2 r; elsewhere it is r_max.
//
// lfs at a boundary point is its distance to the nearest segment other than its own and
// those next to it along the loop (at a polygon vertex: the nearest segment not ending
// there). Sites are laid along every segment a quarter of their own size apart, each
// with the radius kFeatureShare * lfs; r(x) is the smallest site radius plus the
// gradation times the distance to that site, and at most r_max, so it is g-Lipschitz.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "../io/number_text.h"
#include "boundary_grid.h"
#include "disktune/errors.h"
#include "disktune/sizing.h"

namespace disktune {
namespace {

struct Site {
  Vec2 p;
  double r;
};

// A site with the cell of the lookup grid it lies in.
struct SiteCell {
  std::int64_t i, j;
  Site site;
};
bool cell_less(const SiteCell& a, const SiteCell& b) { return std::tie(a.i, a.j) < std::tie(b.i, b.j); }

// The most sites a feature sizing lays down (about a million boundary disks' worth):
// past it a feature is too small for the r_max asked, and laying down more would only
// take long before the job is refused for its size.
constexpr std::size_t kMaxSites = 4'000'000;

// The sites whose radius is below r_max: at each polygon vertex, and along each segment
// a quarter of the local site radius apart. Far from every other part a walk along a
// segment jumps: lfs changes at most as fast as the walk goes (its own and next segments
// stay left out), so no site is needed before lfs could fall below `reach`.
std::vector<Site> feature_sites(const PlanarDomain& domain, double r_max) {
  const detail::BoundaryGrid grid(domain.loops(), domain.frame().origin, domain.frame().origin + domain.frame().extent);
  const std::vector<BoundarySegment> segments = domain.segments();  // the grid's numbering
  const double reach = r_max / kFeatureShare;  // a point at least this far from every other part is no site
  const auto& loops = domain.loops();
  auto next_to = [&](const BoundarySegment& s, const BoundarySegment& o) {
    if (o.loop != s.loop) return false;
    const std::size_t n = loops[s.loop].size();
    return o.index == s.index || o.index == (s.index + 1) % n || s.index == (o.index + 1) % n;
  };
  std::vector<Site> out;
  Site smallest{{}, std::numeric_limits<double>::infinity()};
  auto add = [&](Vec2 p, double lfs) {
    if (kFeatureShare * lfs < smallest.r) smallest = {p, kFeatureShare * lfs};
    if (out.size() == kMaxSites) {
      std::ostringstream msg;
      msg << "feature sizing with r_max = " << r_max << ": the domain has features too small for it (near ("
          << smallest.p.x << ", " << smallest.p.y << ") two boundary parts are " << smallest.r / kFeatureShare
          << " apart, which asks for radii of " << smallest.r << "); widen such gaps, or give a constant radius "
          << "that fits the corners";
      throw InvalidInput(msg.str(), InvalidInput::Remedy::sizing);
    }
    out.push_back({p, kFeatureShare * lfs});
  };
  for (const auto& loop : loops)
    for (const Vec2 v : loop) {
      const double lfs = grid.distance(v, reach, [&](std::size_t o) { return segments[o].a == v || segments[o].b == v; });
      if (lfs < reach) add(v, lfs);
    }
  for (const BoundarySegment& s : segments) {
    const double len = distance(s.a, s.b);
    for (double t = 0; t < len;) {
      const Vec2 p = s.a + (s.b - s.a) * (t / len);
      const double lfs = grid.distance(p, 8 * reach, [&](std::size_t o) { return next_to(s, segments[o]); });
      if (lfs < reach) add(p, lfs);
      t += std::max({0.25 * kFeatureShare * std::min(lfs, reach), lfs - reach, 1e-9 * len});
    }
  }
  return out;
}

}  // namespace

Sizing feature_sizing(std::shared_ptr<const PlanarDomain> domain, double r_max, double gradation) {
  using detail::number_text;
  const std::string params = "r_max = " + number_text(r_max) + ", gradation " + number_text(gradation);
  if (!domain) throw InvalidInput("feature sizing (" + params + ") needs a planar domain");
  if (!std::isfinite(r_max) || !(r_max > 0) || !std::isfinite(gradation) || !(gradation > 0) ||
      !(gradation < 0.5)) {
    throw InvalidInput("feature sizing with " + params +
                       " is not valid: it needs r_max > 0 and 0 < gradation < 0.5 (0.2 keeps Delaunay "
                       "angles above 14.5 degrees; docs/sizing.md)");
  }
  // The sites in cells `reach` wide: every site that can lower r(x) lies in the 3 x 3
  // cells around x, and r(x) is exact.
  const double reach = r_max / gradation;
  auto key = [reach](Vec2 p) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(p.x / reach)),
                                                 static_cast<std::int64_t>(std::floor(p.y / reach))};
  };
  std::vector<SiteCell> cells;
  double smallest = r_max;
  for (const Site& s : feature_sites(*domain, r_max)) {
    const auto [i, j] = key(s.p);
    cells.push_back({i, j, s});
    smallest = std::min(smallest, s.r);
  }
  std::sort(cells.begin(), cells.end(), cell_less);
  const auto shared = std::make_shared<const std::vector<SiteCell>>(std::move(cells));
  std::string description = "feature sizing min(" + number_text(r_max) + ", " + number_text(kFeatureShare) +
                            " lfs graded at " + number_text(gradation) + "), smallest " + number_text(smallest);
  return Sizing(
      [shared, key, r_max, gradation](Vec2 x) {
        double r = r_max;
        const auto [ci, cj] = key(x);
        for (std::int64_t i = ci - 1; i <= ci + 1; ++i)
          for (std::int64_t j = cj - 1; j <= cj + 1; ++j) {
            const auto range = std::equal_range(shared->begin(), shared->end(), SiteCell{i, j, {}}, cell_less);
            for (auto c = range.first; c != range.second; ++c)
              r = std::min(r, c->site.r + gradation * distance(x, c->site.p));
          }
        return r;
      },
      std::move(description));
}

}  // namespace disktune
