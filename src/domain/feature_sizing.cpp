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
#include <cstddef>
#include <limits>
#include <memory>
#include <sstream>
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

// The sites in a kd-tree, searched branch and bound for the smallest s.r + g |x - s.p|:
// a subtree is skipped when its smallest site radius plus g times the distance to its
// box cannot beat the best so far. A grid of cells r_max / g wide holds tens of
// thousands of sites per cell along a thin part (their spacing follows lfs, not
// r_max), which made each evaluation scan them all.
class SiteTree {
 public:
  SiteTree(std::vector<Site> sites, double r_max, double gradation)
      : sites_(std::move(sites)), r_max_(r_max), g_(gradation) {
    if (!sites_.empty()) build(0, 0, sites_.size());
  }

  double operator()(Vec2 x) const {
    double best = r_max_;
    if (!sites_.empty()) search(0, 0, sites_.size(), x, best);
    return best;
  }

 private:
  struct Node {
    Vec2 lo, hi;      // the bounding box of the node's sites
    double smallest;  // their smallest radius
  };
  static constexpr std::size_t kLeaf = 8;

  // Node k holds sites [begin, end); its children are 2k + 1 and 2k + 2, split at the
  // median along the box's longer side.
  void build(std::size_t k, std::size_t begin, std::size_t end) {
    if (nodes_.size() <= k) nodes_.resize(k + 1);
    Node n{sites_[begin].p, sites_[begin].p, sites_[begin].r};
    for (std::size_t i = begin; i < end; ++i) {
      const Site& s = sites_[i];
      n.lo = {std::min(n.lo.x, s.p.x), std::min(n.lo.y, s.p.y)};
      n.hi = {std::max(n.hi.x, s.p.x), std::max(n.hi.y, s.p.y)};
      n.smallest = std::min(n.smallest, s.r);
    }
    nodes_[k] = n;
    if (end - begin <= kLeaf) return;
    const bool along_x = n.hi.x - n.lo.x >= n.hi.y - n.lo.y;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(sites_.begin() + static_cast<std::ptrdiff_t>(begin), sites_.begin() + static_cast<std::ptrdiff_t>(mid),
                     sites_.begin() + static_cast<std::ptrdiff_t>(end),
                     [along_x](const Site& a, const Site& b) { return along_x ? a.p.x < b.p.x : a.p.y < b.p.y; });
    build(2 * k + 1, begin, mid);
    build(2 * k + 2, mid, end);
  }

  double bound(std::size_t k, Vec2 x) const {
    const Node& n = nodes_[k];
    const double dx = std::max({n.lo.x - x.x, 0.0, x.x - n.hi.x}), dy = std::max({n.lo.y - x.y, 0.0, x.y - n.hi.y});
    return n.smallest + g_ * std::hypot(dx, dy);
  }

  void search(std::size_t k, std::size_t begin, std::size_t end, Vec2 x, double& best) const {
    if (bound(k, x) >= best) return;
    if (end - begin <= kLeaf) {
      for (std::size_t i = begin; i < end; ++i) best = std::min(best, sites_[i].r + g_ * distance(x, sites_[i].p));
      return;
    }
    const std::size_t mid = begin + (end - begin) / 2;
    const bool left_first = bound(2 * k + 1, x) <= bound(2 * k + 2, x);  // the likelier winner first prunes more
    if (left_first) {
      search(2 * k + 1, begin, mid, x, best);
      search(2 * k + 2, mid, end, x, best);
    } else {
      search(2 * k + 2, mid, end, x, best);
      search(2 * k + 1, begin, mid, x, best);
    }
  }

  std::vector<Site> sites_;
  std::vector<Node> nodes_;
  double r_max_, g_;
};

// The most sites a feature sizing lays down (about 250,000 boundary disks' worth, a
// job of far more disks inside): past it a feature is too small for the r_max asked, and
// laying down more would only take long before the job is refused for its size. A
// 20-vertex domain 8e9 tall, found by the fuzzer, is refused after 0.5 s at a million
// (1.3 s at 4 million, over 10 s under the sanitizers).
constexpr std::size_t kMaxSites = 1'000'000;

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
    if (!(kFeatureShare * lfs > 0)) {  // closer than a double's square can tell: a radius of 0
      std::ostringstream msg;
      msg << "feature sizing: near (" << p.x << ", " << p.y << ") two boundary parts are " << lfs
          << " apart, closer than the arithmetic can measure (their squared distance is below the smallest "
          << "double); move them apart or remove the vertex there";
      throw InvalidInput(msg.str(), InvalidInput::Remedy::domain);
    }
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
    // lfs is 1-Lipschitz, so from a point lfs - reach from every other part the walk
    // may skip that far. The search reaches at least len / 64 (a segment far from all
    // else takes a few steps, not len / (7 reach): r_max = 1e-9 on the unit square
    // took 9.7 s, found by the fuzzer) and 8 reach (near features, short searches).
    const double search = std::max(8 * reach, len / 64);
    for (double t = 0; t < len;) {
      const Vec2 p = s.a + (s.b - s.a) * (t / len);
      const double lfs = grid.distance(p, search, [&](std::size_t o) { return next_to(s, segments[o]); });
      if (lfs < reach) add(p, lfs);
      t += std::max({0.25 * kFeatureShare * std::min(lfs, reach), lfs - reach, 1e-9 * len});
    }
  }
  return out;
}

}  // namespace

Sizing feature_sizing(std::shared_ptr<const PlanarDomain> domain, double r_max, double gradation) {
  using detail::number_text;
  using detail::short_text;
  const std::string params = "r_max = " + number_text(r_max) + ", gradation " + number_text(gradation);
  if (!domain) throw InvalidInput("feature sizing (" + params + ") needs a planar domain");
  if (!std::isfinite(r_max) || !(r_max > 0) || !std::isfinite(gradation) || !(gradation > 0) ||
      !(gradation < 0.5)) {
    throw InvalidInput("feature sizing with " + params +
                       " is not valid: it needs r_max > 0 and 0 < gradation < 0.5 (0.2 keeps Delaunay "
                       "angles above 14.5 degrees; docs/sizing.md)");
  }
  std::vector<Site> sites = feature_sites(*domain, r_max);
  Site smallest{{}, r_max};
  for (const Site& site : sites)
    if (site.r < smallest.r) smallest = site;
  const auto tree = std::make_shared<const SiteTree>(std::move(sites), r_max, gradation);
  // Where the radius is smallest: what a refusal for the job's size should point at.
  std::string description = "feature sizing min(" + number_text(r_max) + ", " + number_text(kFeatureShare) +
                            " lfs graded at " + number_text(gradation) + "), smallest " + short_text(smallest.r);
  if (smallest.r < r_max) description += " near (" + short_text(smallest.p.x) + ", " + short_text(smallest.p.y) + ")";
  return Sizing([tree](Vec2 x) { return (*tree)(x); },
      std::move(description));
}

}  // namespace disktune
