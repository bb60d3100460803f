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

// From the nearer end: a + (b - a) t near b loses b's digits when |a| dwarfs |b|
// (found by fuzzing: a segment 10^121 long, whose far end gave a distance of 0).
double segment_distance(Vec2 p, const BoundarySegment& s) {
  const Vec2 ab = s.b - s.a;
  const double t = std::clamp(dot(p - s.a, ab) / squared_norm(ab), 0.0, 1.0);
  return t <= 0.5 ? distance(p, s.a + ab * t) : distance(p, s.b - ab * (1 - t));
}

// The segments in the cells of a uniform grid their bounding boxes meet, for nearest
// segment searches that skip some segments.
class SegmentGrid {
 public:
  explicit SegmentGrid(std::vector<BoundarySegment> segments) : segments_(std::move(segments)) {
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi = lo * -1;
    double total = 0;
    for (const BoundarySegment& s : segments_) {
      lo = {std::min({lo.x, s.a.x, s.b.x}), std::min({lo.y, s.a.y, s.b.y})};
      hi = {std::max({hi.x, s.a.x, s.b.x}), std::max({hi.y, s.a.y, s.b.y})};
      total += distance(s.a, s.b);
    }
    origin_ = lo;
    cell_ = std::max(total / static_cast<double>(segments_.size()), 1e-9 * std::max(hi.x - lo.x, hi.y - lo.y));
    for (std::uint32_t k = 0; k < segments_.size(); ++k) {
      const BoundarySegment& s = segments_[k];
      const auto [i0, j0] = cell_of({std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)});
      const auto [i1, j1] = cell_of({std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)});
      for (std::int64_t i = i0; i <= i1; ++i)
        for (std::int64_t j = j0; j <= j1; ++j) entries_.push_back({i, j, k});
    }
    std::sort(entries_.begin(), entries_.end());
    const auto [ni, nj] = cell_of(hi);
    extent_ = std::max(ni, nj) + 1;
  }

  const std::vector<BoundarySegment>& segments() const { return segments_; }

  /// The distance from p to the nearest segment `skip` does not reject, if below `limit`
  /// (else `limit`): rings of cells outward until no nearer segment can be found.
  template <class Skip>
  double nearest(Vec2 p, double limit, Skip&& skip) const {
    const auto [ci, cj] = cell_of(p);
    double best = limit;
    for (std::int64_t ring = 0; (static_cast<double>(ring) - 1) * cell_ < best; ++ring) {
      for (std::int64_t i = ci - ring; i <= ci + ring; ++i)
        for (std::int64_t j = cj - ring; j <= cj + ring; ++j) {
          if (std::max(std::abs(i - ci), std::abs(j - cj)) != ring) continue;
          const auto range = std::equal_range(entries_.begin(), entries_.end(), Entry{i, j, 0}, same_cell);
          for (auto e = range.first; e != range.second; ++e)
            if (!skip(segments_[e->segment])) best = std::min(best, segment_distance(p, segments_[e->segment]));
        }
      if (ring > extent_) break;  // every cell seen
    }
    return best;
  }

 private:
  struct Entry {
    std::int64_t i, j;
    std::uint32_t segment;
    bool operator<(const Entry& o) const { return std::tie(i, j, segment) < std::tie(o.i, o.j, o.segment); }
  };
  static bool same_cell(const Entry& a, const Entry& b) { return std::tie(a.i, a.j) < std::tie(b.i, b.j); }
  std::pair<std::int64_t, std::int64_t> cell_of(Vec2 p) const {
    return {static_cast<std::int64_t>(std::floor((p.x - origin_.x) / cell_)),
            static_cast<std::int64_t>(std::floor((p.y - origin_.y) / cell_))};
  }

  std::vector<BoundarySegment> segments_;
  Vec2 origin_;
  double cell_ = 1;
  std::int64_t extent_ = 0;  // rings around a cell of the box that cover the whole box
  std::vector<Entry> entries_;
};

// The most sites a feature sizing lays down (about a million boundary disks' worth):
// past it a feature is too small for the r_max asked, and laying down more would only
// take long before the job is refused for its size.
constexpr std::size_t kMaxSites = 4'000'000;

// The sites whose radius is below r_max: at each polygon vertex, and along each segment
// a quarter of the local site radius apart. Far from every other part a walk along a
// segment jumps: lfs changes at most as fast as the walk goes (its own and next segments
// stay left out), so no site is needed before lfs could fall below `reach`.
std::vector<Site> feature_sites(const PlanarDomain& domain, double r_max) {
  const SegmentGrid grid(domain.segments());
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
      const double lfs = grid.nearest(v, reach, [&](const BoundarySegment& o) { return o.a == v || o.b == v; });
      if (lfs < reach) add(v, lfs);
    }
  for (const BoundarySegment& s : grid.segments()) {
    const double len = distance(s.a, s.b);
    for (double t = 0; t < len;) {
      const Vec2 p = s.a + (s.b - s.a) * (t / len);
      const double lfs = grid.nearest(p, 8 * reach, [&](const BoundarySegment& o) { return next_to(s, o); });
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
