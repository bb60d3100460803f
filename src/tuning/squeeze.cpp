// SPDX-License-Identifier: GPL-3.0-or-later
// Squeeze injection (beyond the paper): new disks at the largest holes (the Voronoi
// vertices, holes.h), the conflicts they make relaxed as soft disks and then pushed
// apart pair by pair until none is left, then the voids the moves opened refilled. A
// quench, not a slow anneal: the packing stays as random as the sample it starts from
// (docs/tuning.md).
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "../geometry/threads.h"
#include "box_cells.h"
#include "disktune/errors.h"
#include "disktune/geometry.h"
#include "disktune/tuning.h"
#include "disktune/voids.h"
#include "holes.h"
#include "soft_disks.h"
#include "undo_log.h"
#include "void_repair.h"

namespace disktune {
namespace {

// Pushes past the conflict distance: a pair closer than r is moved apart to this many r,
// over-relaxed. A larger target distance or gain converges in fewer pushes but lets the
// packing order itself: at eta 0.80, r = 0.01, gains 1.6 and 1.7: 11-13 % of the disks
// locally hexagonal (1.7 a quarter faster), gain 1.8: 17 %, target 1.01 r: 22 %
// (docs/tuning.md).
constexpr double kPushTo = 1 + 1e-4;
constexpr double kGain = 1.7;
// Soft disks for stages of at least 1 / kSoftShare of the packing, until every pair is
// kSoftStop r apart (then the pushes take over) or for at most kSoftSteps steps (~260 at
// eta 0.80 from the sample).
constexpr std::size_t kSoftShare = 16;
constexpr double kSoftStop = 0.997;
constexpr long kSoftSteps = 2000;

// The disks as plain arrays, relative to the frame's origin, stored cell by cell (cells of
// side at least r + kSlack r, so a cell's disks are contiguous and a sweep in index order
// walks the box cell by cell). A pair within r now was within r + kSlack r when the cells
// were built as long as neither has drifted kSlack r / 2 since: until then the 3 x 3
// cells around a disk hold every disk it can conflict with.
class Quench {
 public:
  static constexpr double kSlack = 0.1;

  Quench(const Frame& frame, double r, std::vector<Vec2> x)
      : r_(r),
        w_(frame.extent.x),
        h_(frame.extent.y),
        x_(std::move(x)),
        nx_(static_cast<int>(w_ / (r * (1 + kSlack)))),
        ny_(static_cast<int>(h_ / (r * (1 + kSlack)))) {
    given_.resize(x_.size());
    for (std::size_t i = 0; i < given_.size(); ++i) given_[i] = static_cast<int>(i);
  }

  // Whether a box has cells enough for 3 x 3 distinct ones around each (3.3 r wide).
  static bool fits(const Frame& frame, double r) {
    return frame.extent.x >= 3 * r * (1 + kSlack) && frame.extent.y >= 3 * r * (1 + kSlack);
  }

  // Pushes every conflicting pair apart, sweep after sweep over the disks that moved in
  // the sweep before (starting with `active`, indices as given), each pair by kGain times
  // half of what brings it to kPushTo r, until a sweep moves nothing. False when that took
  // more than `max_pushes` pushes (then the positions are wherever it stopped).
  bool run(std::vector<int> active, long max_pushes, const std::function<void()>& poll) {
    const int n = static_cast<int>(x_.size());
    build(active);
    std::vector<char> marked(x_.size(), 0);
    std::vector<int> next;
    const double limit2 = 0.25 * kSlack * kSlack * r_ * r_;
    long pushes = 0;
    for (long sweep = 1; !active.empty(); ++sweep) {
      if (poll && sweep % detail::kPollSteps == 0) poll();
      bool drifted = false;
      auto moved = [&](int i) {
        if (!marked[i]) marked[i] = 1, next.push_back(i);
        drifted = drifted || squared_norm(x_[i] - built_at_[i]) > limit2;
      };
      for (const int i : active) {
        const int cx = cell_of_[i] % nx_, cy = cell_of_[i] / nx_;
        bool pushed = false;
        for (int dy = -1; dy <= 1; ++dy) {
          const int y = cy + dy, wy = y < 0 ? ny_ - 1 : y == ny_ ? 0 : y;
          const double sy = y < 0 ? -h_ : y == ny_ ? h_ : 0;  // the image across the seam
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = cx + dx, wx = x < 0 ? nx_ - 1 : x == nx_ ? 0 : x;
            const Vec2 shift{x < 0 ? -w_ : x == nx_ ? w_ : 0, sy};
            const int cell = wy * nx_ + wx;
            for (int j = start_[cell]; j < start_[cell + 1]; ++j) {
              if (j == i) continue;
              Vec2 d = x_[j] + shift - x_[i];
              const double d2 = squared_norm(d);
              if (d2 >= r_ * r_) continue;
              const double dist = std::sqrt(d2);
              if (dist == 0) d = {r_, 0};  // coinciding centers: any direction
              const Vec2 step = d * (kGain * 0.5 * (kPushTo * r_ - dist) / std::max(dist, r_));
              x_[i] -= step;
              x_[j] += step;
              moved(j);
              pushed = true;
              ++pushes;
            }
          }
        }
        if (pushed) moved(i);
      }
      // The next sweep in index order, that is cell by cell.
      if (next.size() * 16 > x_.size()) {
        next.clear();
        for (int i = 0; i < n; ++i)
          if (marked[i]) next.push_back(i);
      } else {
        std::sort(next.begin(), next.end());
      }
      for (const int j : next) marked[j] = 0;
      active.swap(next);
      next.clear();
      if (pushes > max_pushes) return false;
      if (drifted) build(active);
    }
    return true;
  }

  // Where each disk ended, in the order given, in [0, W) x [0, H) (origin not added).
  std::vector<Vec2> positions() const { return detail::in_given_order(x_, given_, {w_, h_}); }
  // The index each disk was given by, cell by cell (rows of cells from the origin).
  const std::vector<int>& given_by_place() const { return given_; }

 private:
  // Sorts the disks by cell (counting sort, stable) and notes where each was; `active`
  // (indices before) is renumbered and comes out in increasing order.
  void build(std::vector<int>& active) {
    const std::size_t n = x_.size();
    std::vector<int> cell;
    detail::count_by_cell(x_, {w_, h_}, nx_, ny_, cell, start_);
    std::vector<int> fill(start_.begin(), start_.end() - 1), to(n), given(n);
    std::vector<Vec2> x(n);
    cell_of_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int k = fill[cell[i]]++;
      to[i] = k;
      x[k] = x_[i];
      given[k] = given_[i];
      cell_of_[k] = cell[i];
    }
    x_.swap(x);
    given_.swap(given);
    for (int& a : active) a = to[a];
    std::sort(active.begin(), active.end());
    built_at_ = x_;
  }

  double r_, w_, h_;
  std::vector<Vec2> x_, built_at_;
  int nx_, ny_;
  std::vector<int> start_, cell_of_;
  std::vector<int> given_;  // the index each disk was given by
};

// The holes taken for new disks, no two closer than r: at most one in each cell of side
// at most r / sqrt(2), so a hole is checked against the 5 x 5 cells around its own.
class TakenHoles {
 public:
  TakenHoles(const Frame& frame, double r)
      : frame_(frame),
        r_(r),
        nx_(static_cast<int>(std::ceil(frame.extent.x * std::sqrt(2.0) / r))),
        ny_(static_cast<int>(std::ceil(frame.extent.y * std::sqrt(2.0) / r))),
        taken_(static_cast<std::size_t>(nx_) * ny_, Vec2{-1, -1}) {}

  // Takes the hole unless it lies closer than r to one taken (then false).
  bool take(Vec2 hole) {
    const Vec2 at = hole - frame_.origin;
    const int cx = std::min(nx_ - 1, static_cast<int>(at.x / frame_.extent.x * nx_));
    const int cy = std::min(ny_ - 1, static_cast<int>(at.y / frame_.extent.y * ny_));
    for (int dy = -2; dy <= 2; ++dy) {
      const int y = (cy + dy + ny_) % ny_;
      for (int dx = -2; dx <= 2; ++dx) {
        const Vec2 other = taken_[y * nx_ + (cx + dx + nx_) % nx_];
        if (other.x < 0) continue;
        Vec2 d = other - at;
        d.x -= frame_.extent.x * std::round(d.x / frame_.extent.x);
        d.y -= frame_.extent.y * std::round(d.y / frame_.extent.y);
        if (squared_norm(d) < r_ * r_) return false;
      }
    }
    taken_[cy * nx_ + cx] = at;
    return true;
  }

 private:
  const Frame& frame_;
  double r_;
  int nx_, ny_;
  std::vector<Vec2> taken_;  // relative to the origin; x < 0 where none
};

// One stage: `count` disks at the largest holes (no two closer than r), their conflicts
// pushed apart, the voids refilled. Returns the disks added, or -1 when the pushes did not
// settle within their budget (the packing is then as it was: the moves are worked out on
// copies of the centers and made only once they settle). `poll` is called while they
// are worked out, the packing untouched. Once they settle the packing is made anew, its
// disks numbered cell by cell, and the one it replaces is handed back in `replaced` (to
// take the stage back).
long squeeze_stage(Packing& packing, std::size_t count, Rng& rng, std::vector<DiskId>& refilled,
                   const std::function<void()>& poll, std::optional<Packing>& replaced) {
  const double r = packing.max_radius();
  const Frame& frame = packing.frame();
  const std::size_t before = packing.size();
  std::vector<DiskId> ids = packing.ids();
  std::vector<Vec2> old_centers, x;  // x: the disks there, then the new ones
  old_centers.reserve(ids.size());
  for (const DiskId id : ids) old_centers.push_back(packing.center(id));
  x.reserve(ids.size() + count);
  for (const Vec2 c : old_centers) x.push_back(c - frame.origin);
  TakenHoles taken(frame, r);
  std::vector<int> active;
  for (const Vec2 hole : detail::holes_largest_first(packing, detail::thread_count(0))) {
    if (active.size() == count) break;
    if (!taken.take(hole)) continue;
    active.push_back(static_cast<int>(x.size()));
    x.push_back(hole - frame.origin);
  }
  // Many new disks push the whole packing: soft disks (every disk moving at once, on
  // every core) bring it near a valid one in a few hundred steps, the pair pushes settle
  // the last gaps, which they do faster (soft_disks.h). A few new disks are pushed apart
  // by the pair pushes alone, which touch only the disks near them.
  std::vector<int> everyone;
  if (count * kSoftShare >= x.size()) {
    detail::relax_soft_disks(frame, r, x, kSoftStop * r, kSoftSteps, detail::thread_count(0), poll);
    everyone.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) everyone[i] = static_cast<int>(i);
    active.swap(everyone);
  }
  // Several times what settling takes at eta 0.80 from the sample (740 pushes a new disk
  // at gain 1.6, r = 0.01), so that a stage past where the packing jams gives up at a
  // bounded cost.
  const long budget = 4000 * static_cast<long>(count) + 100 * static_cast<long>(x.size());
  Quench quench(frame, r, std::move(x));
  if (!quench.run(std::move(active), budget, poll)) return -1;
  // Every disk has moved: a packing made anew, disk after disk in order of place, costs
  // less than moving each (0.36-0.52 against 0.66-0.80 s at 1.5 M disks), and its ids in
  // that order keep the neighbours of consecutive disks close in memory for what reads
  // them in id order (tune's final check 1.55-1.81 -> 1.04-1.24 s there).
  {
    const std::vector<Vec2> ended = quench.positions();
    Packing placed(frame, r);
    std::vector<DiskId> id_of(ended.size());
    for (const int i : quench.given_by_place()) {
      const bool old = static_cast<std::size_t>(i) < old_centers.size();
      id_of[i] = placed.insert(ended[i] + frame.origin, r, old ? packing.flags(ids[i]) : 0);
    }
    replaced = std::exchange(packing, std::move(placed));
    ids.swap(id_of);
  }
  // Only what a moved disk covered before can be uncovered now (the packing was maximal,
  // and new disks only add cover): refill each such disk's old place. Most hold no void:
  // they are found on every core, the packing unchanged, and only the others refilled in
  // order; a refill only adds cover, so a place found void-free stays so, and the
  // packing is the one refilling every place in order would give.
  std::vector<std::size_t> open;
  detail::ordered_chunks<std::vector<std::size_t>>(
      old_centers.size(), detail::thread_count(0),
      [&](std::size_t from, std::size_t to, std::vector<std::size_t>& part) {
        std::vector<Corner> corners;
        for (std::size_t i = from; i < to; ++i) {
          if (old_centers[i] == packing.center(ids[i])) continue;
          corners.clear();
          corners_in_region(packing, old_centers[i], r, {}, corners);
          if (!corners.empty()) part.push_back(i);
        }
      },
      [&](const std::vector<std::size_t>& part) {
        open.insert(open.end(), part.begin(), part.end());
      });
  const std::size_t settled = packing.size();
  detail::UndoLog log(packing);
  for (const std::size_t i : open)
    detail::repair_void(log, packing, old_centers[i], r, rng, static_cast<std::size_t>(-2));
  log.commit();
  refilled.clear();
  if (packing.size() > settled) {  // the disks neither there before nor put at a hole
    std::vector<char> known(packing.id_bound(), 0);
    for (const DiskId id : ids) known[id] = 1;
    for (const DiskId id : packing.ids())
      if (!known[id]) refilled.push_back(id);
  }
  return static_cast<long>(packing.size()) - static_cast<long>(before);
}

// Takes `count` disks back out after a refill passed the count: attractor ejection, then
// sifting, of the disks the refill put in the voids (where there is most room to close
// over them), then of any. Each is a single operation that keeps the packing valid.
// Returns how many it removed.
std::size_t eject_after_refill(Packing& packing, const std::vector<DiskId>& refilled,
                               std::size_t count, Rng& rng) {
  std::size_t removed = 0;
  auto each = [&](const std::vector<DiskId>& disks) {
    for (const auto op : {&attractor_eject, &sift_eject}) {
      for (const DiskId p : disks) {
        if (removed == count) return;
        if (!packing.alive(p)) continue;
        removed += op(packing, p, rng, count - removed);
      }
    }
  };
  each(refilled);
  if (removed < count) each(packing.ids());
  return removed;
}

}  // namespace

std::size_t squeeze_inject(Packing& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step,
                           const std::function<void()>& poll) {
  if (!packing.frame().periodic || packing.domain() || packing.sizing()) {
    throw InvalidInput(
        "squeeze injection moves disks through the seams of a periodic box with one "
        "radius; in a planar domain or with a sizing use void or repeller injection");
  }
  if (!Quench::fits(packing.frame(), packing.max_radius()) ||
      !detail::soft_disks_fit(packing.frame(), packing.max_radius())) {
    return 0;
  }
  std::vector<DiskId> refilled;
  for (std::size_t want = max_added; want > 0;) {
    std::optional<Packing> before;  // the packing a settled stage replaced
    const long got = squeeze_stage(packing, want, rng, refilled, poll, before);
    if (got >= 0) {
      // The refill can pass the count (2 disks from the sample of 111,453 to eta 0.80, 1
      // to 0.70): as many are taken out again, rather than the whole stage done again.
      const auto added = static_cast<std::size_t>(got);
      if (added <= max_added ||
          eject_after_refill(packing, refilled, added - max_added, rng) == added - max_added) {
        if (after_step) after_step();
        return std::min(added, max_added);
      }
    }
    // Not settled (smaller stages settle where one big one does not), or the count not
    // brought back: the stage is taken back and tried smaller.
    if (before) packing = std::move(*before);
    if (got < 0 && want < std::max<std::size_t>(packing.size() / 64, 2)) break;
    const std::size_t over = got < 0 ? want / 2 : static_cast<std::size_t>(got) - max_added;
    want = want > over ? want - over : 0;
  }
  return 0;
}

}  // namespace disktune
