// SPDX-License-Identifier: GPL-3.0-or-later
#include "soft_disks.h"

#include <algorithm>
#include <cmath>

#include "../geometry/threads.h"
#include "box_cells.h"

namespace disktune::detail {
namespace {

// The springs rest at r (1 + kMargin), so that pairs end a little past r without a long
// wait for the last gaps to open. A larger margin ends sooner but lets the packing order
// itself (docs/tuning.md, "Soft disks first").
constexpr double kMargin = 1e-3;
// The pair lists reach rest + kSkin r; they are made again once some disk has moved
// kSkin r / 2 since (until then no pair closer than rest is missing from them).
constexpr double kSkin = 0.2;
// FIRE's published parameters but the largest step; time in units of a spring's period
// over 2 pi, so they do not depend on r. The largest step stays under what the stiffest
// motion allows (a disk between six springs: about 2 / sqrt(6) = 0.8), where steps of 1.0
// overshot and restarted again and again: 10^6 disks to eta 0.80 in 190 steps instead of
// 308 (0.75: 176, 0.8: 250), a few tenths of a point more disks locally hexagonal
// (docs/tuning.md).
constexpr double kDtStart = 0.1, kDtMax = 0.7, kDtMin = 0.002, kDtGrow = 1.1, kDtShrink = 0.5;
constexpr double kAlphaStart = 0.1, kAlphaShrink = 0.99;
constexpr int kDelay = 5;

// The disks stored cell by cell (cells at least rest + skin wide, rows of cells in
// strips), and each strip's pairs within reach listed disk by disk: each disk with those
// after it in its own cell and in the cell to its right and the three above (so each
// pair once). A pair closer than rest pushes
// both disks apart by (rest^2 - d^2) / (2 rest^2) of their distance d: the spring's push
// near contact, without a square root. A strip adds each pair's push to both disks, so it
// writes into the first row of the strip above it (the last strip into strip 0's): the
// even strips run together, then the odd ones, each strip in its own order; so every sum
// is made in the same order on any number of threads.
class SoftDisks {
 public:
  SoftDisks(const Frame& frame, double r, std::vector<Vec2> x, unsigned threads)
      : w_(frame.extent.x),
        h_(frame.extent.y),
        rest_(r * (1 + kMargin)),
        skin_(kSkin * r),
        nx_(static_cast<int>(w_ / (rest_ + skin_))),
        ny_(static_cast<int>(h_ / (rest_ + skin_))),
        strips_(ny_ >= 4 ? std::min(64, (ny_ / 2) & ~1) : 1),
        threads_(threads),
        x_(std::move(x)),
        v_(x_.size(), Vec2{}),
        f_(x_.size(), Vec2{}),
        given_(x_.size()),
        lists_(strips_),
        listed_(strips_),
        sums_(strips_) {
    for (std::size_t i = 0; i < given_.size(); ++i) given_[i] = static_cast<int>(i);
  }

  static bool fits(const Frame& frame, double r) {
    const double cell = r * (1 + kMargin + kSkin);
    return frame.extent.x >= 3 * cell && frame.extent.y >= 3 * cell;
  }

  bool relax(double stop, long max_steps, const std::function<void()>& poll) {
    build();
    double dt = kDtStart, alpha = kAlphaStart;
    double drift = 0, fastest_before = 0;
    int uphill_free = 0;  // steps since the last restart
    for (long step = 0;; ++step) {
      if (closest_after_forces() >= stop) return true;
      if (step == max_steps) return false;
      if (poll && step % kPollSteps == kPollSteps - 1) poll();
      // FIRE: power P = F.v; downhill keeps going and speeds up, uphill stops dead.
      Sums total;
      for (const Sums& sum : sums_) {
        total.power += sum.power, total.force2 += sum.force2, total.velocity2 += sum.velocity2;
      }
      bool restart = false;
      if (total.power > 0) {
        if (++uphill_free > kDelay) dt = std::min(dt * kDtGrow, kDtMax), alpha *= kAlphaShrink;
      } else {
        uphill_free = 0, restart = true;
        dt = std::max(dt * kDtShrink, kDtMin), alpha = kAlphaStart;
      }
      // v + dt F, then mixed toward F's direction at v's length: |v + dt F| from the sums.
      const double kept = restart ? 0 : 1;
      const double speed2 =
          kept * (total.velocity2 + 2 * dt * total.power) + dt * dt * total.force2;
      const double steer =
          total.force2 > 0 ? alpha * std::sqrt(std::max(speed2, 0.0) / total.force2) : 0;
      std::vector<double> fastest2(strips_, 0);
      each_strip_in_parallel([&](int s) {
        double most = 0;
        for (int i = first_of(s), end = first_of(s + 1); i < end; ++i) {
          Vec2 v = v_[i] * kept;
          if (restart) x_[i] -= v_[i] * (0.5 * dt);  // FIRE 2.0: half a step back
          v = (v + f_[i] * dt) * (1 - alpha) + f_[i] * steer;
          v_[i] = v;
          f_[i] = Vec2{};  // for the next step's forces
          x_[i] += v * dt;
          most = std::max(most, squared_norm(v));
        }
        fastest2[s] = most;
      });
      // No disk has moved farther since the lists were made than the steps' largest
      // moves added up (half steps back included).
      drift += dt * std::sqrt(*std::max_element(fastest2.begin(), fastest2.end())) +
               (restart ? 0.5 * dt * fastest_before : 0);
      fastest_before = std::sqrt(*std::max_element(fastest2.begin(), fastest2.end()));
      if (drift > 0.5 * skin_) build(), drift = 0;
    }
  }

  // Where each disk ended, in the order given, in [0, W) x [0, H) (origin not added).
  std::vector<Vec2> positions() const { return in_given_order(x_, given_, {w_, h_}); }

 private:
  struct Sums {
    double power = 0, force2 = 0, velocity2 = 0;
  };
  static double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
  int first_row(int strip) const { return strip * ny_ / strips_; }
  int first_of(int strip) const { return start_[first_row(strip) * nx_]; }

  template <class Job>
  void each_strip_in_parallel(Job&& job) {
    parallel_for(static_cast<std::size_t>(strips_), threads_,
                 [&](std::size_t s, unsigned) { job(static_cast<int>(s)); });
  }

  // Sorts the disks by cell (counting sort) and makes each strip's lists. The arrays
  // sorted into are kept from one build to the next: fresh ones had to be faulted in
  // each time (at 1.46 M disks 14 ms a build, a third of the sort's time).
  void build() {
    const std::size_t n = x_.size();
    std::vector<int>& cell = cell_;
    count_by_cell(x_, {w_, h_}, nx_, ny_, cell, start_, threads_);
    fill_.assign(start_.begin(), start_.end() - 1);
    sorted_x_.resize(n), sorted_v_.resize(n), sorted_given_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int k = fill_[cell[i]]++;
      sorted_x_[k] = x_[i], sorted_v_[k] = v_[i], sorted_given_[k] = given_[i];
    }
    x_.swap(sorted_x_), v_.swap(sorted_v_), given_.swap(sorted_given_);
    const double reach2 = (rest_ + skin_) * (rest_ + skin_);
    each_strip_in_parallel([&](int s) {
      std::vector<Pair>& list = lists_[s];
      int used = 0;
      for (int cy = first_row(s); cy < first_row(s + 1); ++cy) {
        const int up = cy + 1 < ny_ ? cy + 1 : 0;
        for (int cx = 0; cx < nx_; ++cx) {
          const int left = cx > 0 ? cx - 1 : nx_ - 1, right = cx + 1 < nx_ ? cx + 1 : 0;
          // The cell's own disks, then half the cells around it: each pair of cells once.
          const int cells[] = {cy * nx_ + right, up * nx_ + left, up * nx_ + cx, up * nx_ + right};
          const int c = cy * nx_ + cx;
          int around = start_[c + 1] - start_[c];
          for (const int other : cells) around += start_[other + 1] - start_[other];
          for (int i = start_[c]; i < start_[c + 1]; ++i) {
            if (list.size() < static_cast<std::size_t>(used + around))
              list.resize(2 * (used + around));
            Pair* out = list.data();
            const Vec2 xi = x_[i];
            // Every candidate written, kept by moving on only when within reach: no branch
            // to mispredict (about half are kept).
            for (int j = i + 1; j < start_[c + 1]; ++j) {
              out[used] = {i, j};
              used += squared_norm(apart(xi, x_[j])) < reach2;
            }
            for (const int other : cells) {
              for (int j = start_[other]; j < start_[other + 1]; ++j) {
                out[used] = {i, j};
                used += squared_norm(apart(xi, x_[j])) < reach2;
              }
            }
          }
        }
      }
      listed_[s] = used;
    });
  }

  // From a to the nearest image of b (no disk has moved far from where the lists wrapped
  // it into the box).
  Vec2 apart(Vec2 a, Vec2 b) const {
    Vec2 u = b - a;
    if (u.x > 0.5 * w_)
      u.x -= w_;
    else if (u.x < -0.5 * w_)
      u.x += w_;
    if (u.y > 0.5 * h_)
      u.y -= h_;
    else if (u.y < -0.5 * h_)
      u.y += h_;
    return u;
  }

  // FIRE's sums over strip s's disks, their forces all added (each strip's in the same
  // order on any number of threads).
  void sum_strip(int s) {
    Sums& sum = sums_[s];
    sum = {};
    for (int i = first_of(s), end = first_of(s + 1); i < end; ++i) {
      sum.power += dot(f_[i], v_[i]);
      sum.force2 += dot(f_[i], f_[i]);
      sum.velocity2 += dot(v_[i], v_[i]);
    }
  }

  // Every disk's push from the springs now, and each strip's sums; returns the smallest
  // distance of a pair (rest when none is closer).
  double closest_after_forces() {
    std::vector<double> closest2(strips_);
    const double rest2 = rest_ * rest_, stiffness = 0.5 / rest2;
    auto strip = [&](int s) {
      double m = rest2;  // rest when no pair is closer
      const Pair* list = lists_[s].data();
      const Vec2* x = x_.data();
      Vec2* f = f_.data();
      // One flat loop over the pairs: a loop per disk over its two or three pairs took
      // a fifth longer (5.4 against 4.4 s for a stage of 1.46 M disks on two cores).
      for (int k = 0, n = listed_[s]; k < n; ++k) {
        const int i = list[k].i, j = list[k].j;
        const Vec2 u = apart(x[i], x[j]);
        const double d2 = squared_norm(u);
        m = std::min(m, d2);
        // max(rest2 - d2, 0) without a branch: about half the listed pairs overlap,
        // at random, and a branch mispredicted costs more than the arithmetic.
        const double gap = rest2 - d2, over = 0.5 * (gap + std::fabs(gap));
        const Vec2 push = u * (over * stiffness);
        f[i] -= push;
        f[j] += push;
      }
      closest2[s] = m;
    };
    if (strips_ == 1) {
      strip(0);
      sum_strip(0);
    } else {
      parallel_for(static_cast<std::size_t>(strips_ / 2), threads_,
                   [&](std::size_t k, unsigned) { strip(2 * static_cast<int>(k)); });
      // Odd strip s adds the last pushes to itself and to the first row of the even strip
      // above it (no other strip does): both strips' sums are made there, strip s still
      // in the cache (a pass of its own over every disk cost 2 ms a step at 1.46 M).
      parallel_for(static_cast<std::size_t>(strips_ / 2), threads_, [&](std::size_t k, unsigned) {
        const int s = 2 * static_cast<int>(k) + 1;
        strip(s);
        sum_strip(s);
        sum_strip((s + 1) % strips_);
      });
    }
    return std::sqrt(*std::min_element(closest2.begin(), closest2.end()));
  }

  double w_, h_, rest_, skin_;
  int nx_, ny_, strips_;
  unsigned threads_;
  std::vector<Vec2> x_, v_, f_, sorted_x_, sorted_v_;
  std::vector<int> cell_, fill_, sorted_given_;  // scratch for the sort
  std::vector<int> given_;               // the index each disk was given by
  std::vector<int> start_;               // each cell's first disk
  struct Pair {
    int i, j;
  };
  std::vector<std::vector<Pair>> lists_;  // each strip's pairs, disk by disk
  std::vector<int> listed_;               // how much of each strip's list is used
  std::vector<Sums> sums_;
};

}  // namespace

bool soft_disks_fit(const Frame& frame, double r) { return SoftDisks::fits(frame, r); }

bool relax_soft_disks(const Frame& frame, double r, std::vector<Vec2>& x, double stop,
                      long max_steps, unsigned threads, const std::function<void()>& poll) {
  SoftDisks disks(frame, r, std::move(x), threads);
  const bool reached = disks.relax(stop, max_steps, poll);
  x = disks.positions();
  return reached;
}

}  // namespace disktune::detail
