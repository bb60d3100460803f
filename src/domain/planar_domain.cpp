// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/planar_domain.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <tuple>

#include "boundary_grid.h"
#include "disktune/errors.h"
#include "disktune/tolerance.h"
#include "loop_validation.h"
#include "radius_limits.h"
#include "point_text.h"

namespace disktune {
namespace {

using detail::point_text;

// A suggested radius in a message, to 4 significant digits, rounded the safe way.
double round_4_digits(double x, bool up) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 3);
  return (up ? std::ceil(x / unit) : std::floor(x / unit)) * unit;
}

}  // namespace

// The grid's own type stays out of the public header.
struct PlanarDomain::CellGrid : detail::BoundaryGrid {
  using BoundaryGrid::BoundaryGrid;
};

PlanarDomain::PlanarDomain(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes) {
  loops_.reserve(holes.size() + 1);
  loops_.push_back(std::move(outer));
  for (auto& hole : holes) loops_.push_back(std::move(hole));
  detail::validate_loops(loops_);

  // The domain on the left of every segment: outer counterclockwise, holes clockwise.
  // Reversal keeps vertex 0 first, so indices in later messages stay recognisable.
  double twice_area = 0;
  for (std::size_t k = 0; k < loops_.size(); ++k) {
    const double a = detail::twice_signed_area(loops_[k]);
    if ((k == 0) != (a > 0)) std::reverse(loops_[k].begin() + 1, loops_[k].end());
    twice_area += k == 0 ? std::abs(a) : -std::abs(a);
  }
  area_ = 0.5 * twice_area;

  Vec2 lo = loops_[0][0], hi = lo;  // holes lie inside the outer loop
  for (const Vec2 p : loops_[0]) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  frame_ = Frame{lo, hi - lo, false};
  grid_ = std::make_shared<const CellGrid>(loops_, lo, hi);
}

std::vector<BoundarySegment> PlanarDomain::segments() const {
  std::vector<BoundarySegment> out;
  for (std::size_t k = 0; k < loops_.size(); ++k) {
    const std::size_t n = loops_[k].size();
    for (std::size_t i = 0; i < n; ++i) out.push_back({loops_[k][i], loops_[k][(i + 1) % n], k, i});
  }
  return out;
}

bool PlanarDomain::contains(Vec2 p) const { return grid_->contains(p); }

double PlanarDomain::distance_to_boundary(Vec2 p) const { return grid_->distance(p); }

Vec2 PlanarDomain::random_point(Rng& rng) const {
  // Rejection from the bounding box: accepted points are uniform over the domain.
  for (;;) {
    const double x = uniform01(rng), y = uniform01(rng);
    const Vec2 p = frame_.origin + Vec2{x * frame_.extent.x, y * frame_.extent.y};
    if (contains(p)) return p;
  }
}

// The closest two corners closer than r, as (loop, index) pairs and their squared
// distance, if any.
std::optional<PlanarDomain::CornerPair> PlanarDomain::conflicting_corners(double r) const {
  // A disk sits on every corner: corners closer than r would conflict. Bin the corners
  // in cells of side r (sorted keys, so tiny r costs no memory) and compare neighbours.
  struct Corner {
    std::int64_t ci, cj;
    std::size_t loop, index;
  };
  std::vector<Corner> corners;
  for (std::size_t k = 0; k < loops_.size(); ++k) {
    for (std::size_t i = 0; i < loops_[k].size(); ++i) {
      const Vec2 q = (loops_[k][i] - frame_.origin) * (1.0 / r);
      corners.push_back({static_cast<std::int64_t>(q.x), static_cast<std::int64_t>(q.y), k, i});
    }
  }
  auto cell_less = [](const Corner& u, const Corner& v) {
    return std::tie(u.ci, u.cj) < std::tie(v.ci, v.cj);
  };
  std::sort(corners.begin(), corners.end(), cell_less);
  const Corner* first = nullptr;
  const Corner* second = nullptr;
  double best2 = std::numeric_limits<double>::infinity();
  for (const Corner& u : corners) {
    const Vec2 pu = loops_[u.loop][u.index];
    for (std::int64_t di = -1; di <= 1; ++di) {
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        const Corner key{u.ci + di, u.cj + dj, 0, 0};
        auto range = std::equal_range(corners.begin(), corners.end(), key, cell_less);
        for (auto v = range.first; v != range.second; ++v) {
          if (std::tie(v->loop, v->index) <= std::tie(u.loop, u.index)) continue;  // each pair once
          const double d2 = squared_distance(pu, loops_[v->loop][v->index]);
          if (is_conflict(d2, r) && d2 < best2) best2 = d2, first = &u, second = &*v;
        }
      }
    }
  }
  if (!first) return std::nullopt;
  return CornerPair{{first->loop, first->index}, {second->loop, second->index}, best2};
}

bool PlanarDomain::corners_fit(double r) const { return !conflicting_corners(r); }

void PlanarDomain::validate_radius(double r) const {
  std::ostringstream domain;
  domain << "this domain of area " << area_;
  detail::check_radius_for_area(r, area_, domain.str());
  if (const auto pair = conflicting_corners(r)) {
    const auto& [first, second, best2] = *pair;
    const Vec2 p = loops_[first[0]][first[1]], q = loops_[second[0]][second[1]];
    std::ostringstream msg;
    msg << "radius " << r << " is too large for this domain: corners "
        << detail::loop_text(first[0]) << ", vertex " << first[1] << ' ' << point_text(p)
        << ", and " << detail::loop_text(second[0]) << ", vertex " << second[1] << ' '
        << point_text(q) << ", are only " << std::sqrt(best2)
        << " apart, and each corner holds a disk; use r <= "
        << round_4_digits(std::sqrt(best2), false);
    throw InvalidInput(msg.str());
  }
}

}  // namespace disktune
