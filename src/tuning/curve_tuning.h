// SPDX-License-Identifier: GPL-3.0-or-later
// 1D tuning of boundary curves (paper, section 7: "we first adjust the spacing of these
// disks using one-dimensional disk injection or ejection, respecting the sizing function,
// and keeping disk centers on the boundary curves"), written once for every kind of
// domain over a small adapter (internal).
//
// A curve is a polyline: a planar domain's segment between two corners (open; the corner
// disks at its ends never move), or a surface's open boundary loop (closed; no disk is
// pinned). A boundary disk is a fixed disk whose center lies on a curve, known by its arc
// length s along it. Every step plans its whole boundary change first and applies it
// only when, afterwards,
//  - boundary centers are at least max(r_i, r_j) apart in space (chord distance, also
//    across curves that come close or meet at a sharp corner), and
//  - every boundary point that lost a covering disk is covered by a boundary disk again
//    (1D maximality; checked on every curve piece the old disks reached);
// then interior disks in conflict with a moved or new boundary disk (the latest arrival)
// are removed, and every region a disk left is refilled (repair_void), so the whole
// packing stays conflict-free and maximal after each step.
//
// The adapter A supplies:
//   using Pack (Packing or SurfacePacking), Pos (Vec2 or Vec3), Point (what the packing
//   inserts: Vec2 or SurfacePoint);
//   Pack& packing();
//   std::vector<Curve<Pos>> curves() const;
//   Point point_at(const Curve<Pos>& c, std::size_t piece, double t) const;
//   static Pos pos(const Point&);
//   double radius_at(const Point&) const;           // the sizing, at a boundary point
//   void for_each_near(Pos q, double R, F f) const; // f(DiskId) for centers within R of q
//   void repair(BasicUndoLog<Pack>&, Pos c, double r, Rng&) const;  // refill D(c, r)
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/random.h"
#include "disktune/tolerance.h"
#include "disktune/vec3.h"
#include "undo_log.h"

namespace disktune::detail {

inline std::array<double, 3> coords(Vec2 p) { return {p.x, p.y, 0}; }
inline std::array<double, 3> coords(Vec3 p) { return {p.x, p.y, p.z}; }

/// A boundary curve: piece k runs from v[k] to v[k + 1] (a closed curve's last piece back
/// to v[0]); at[k] is the arc length at v[k], at.back() the whole length.
template <class Pos>
struct Curve {
  std::vector<Pos> v;
  std::vector<double> at;
  bool closed = false;
  std::size_t tag = 0;  // the adapter's name for the curve (a surface's loop index)

  Curve(std::vector<Pos> vertices, bool is_closed, std::size_t name)
      : v(std::move(vertices)), closed(is_closed), tag(name) {
    at.push_back(0);
    for (std::size_t k = 0; k + 1 < v.size() + (closed ? 1 : 0); ++k) at.push_back(at.back() + norm(b(k) - a(k)));
  }
  std::size_t pieces() const { return at.size() - 1; }
  double length() const { return at.back(); }
  Pos a(std::size_t k) const { return v[k]; }
  Pos b(std::size_t k) const { return v[(k + 1) % v.size()]; }
};

/// What one step did: whether it changed the packing, and the net number of boundary
/// disks it added (negative: removed).
struct CurveStep {
  bool applied = false;
  long added = 0;
};

template <class A>
class CurveTuner {
 public:
  using Pack = typename A::Pack;
  using Pos = typename A::Pos;
  using Point = typename A::Point;

  explicit CurveTuner(A& adapter)
      : a_(adapter), packing_(adapter.packing()), curves_(adapter.curves()), rmax_(packing_.max_radius()),
        tol_(1e-9 * rmax_), cell_(2.5 * rmax_) {
    disks_.resize(curves_.size());
    for (std::size_t c = 0; c < curves_.size(); ++c) {
      find_disks(c);
      index_pieces(c);
    }
  }

  /// Movable boundary disks on curve c.
  std::size_t movable_count(std::size_t c) const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < disks_[c].size(); ++i) n += movable(c, i);
    return n;
  }
  std::size_t curve_count() const { return curves_.size(); }

  /// The number of movable disks curve c should hold at spacing `factor` r(s): the
  /// integral of ds / (factor r(s)) steps (as in a hexagonal packing's boundary), but
  /// never so few that even steps exceed `longest` r, kept within what 1D maximality
  /// (steps <= 2r) and conflict-freedom (steps >= r) allow.
  std::size_t target(std::size_t c, double factor, double longest) const {
    const Curve<Pos>& cv = curves_[c];
    const double len = cv.length();
    const int pieces = 64;
    double sum = 0, r_min = 1e300, r_max = 0;
    for (int k = 0; k < pieces; ++k) {  // midpoint rule
      const double r = a_.radius_at(point_at_arc(c, len * (k + 0.5) / pieces));
      r_min = std::min(r_min, r), r_max = std::max(r_max, r);
      sum += len / pieces / (factor * r);
    }
    const double lo = std::ceil(len / (2 * r_min) * (1 - 1e-12)), hi = std::floor(len / r_max * (1 + 1e-12));
    const double fewest = std::max(lo, cv.closed ? 3.0 : 1.0), most = std::max(hi, fewest);
    const double close = std::ceil(sum * factor / longest * (1 - 1e-12));
    const double n = std::clamp(std::max(std::round(sum), close), fewest, most);
    return static_cast<std::size_t>(n) - (cv.closed ? 0 : 1);
  }

  /// Injection or ejection steps at random movable disks of curve c until it holds
  /// `goal` movable disks, or no step has changed the count for a long while (then the
  /// curve keeps what it has). Where the step at the drawn disk changes no count (random
  /// gaps block it), its wide form (respread) at the same disk is tried. Returns the net
  /// number of disks added.
  long tune_curve(std::size_t c, std::size_t goal, Rng& rng) {
    long net = 0;
    std::size_t count = movable_count(c);
    const std::size_t patience = 4 * (std::max(goal, count) + 4);
    std::size_t budget = 10 * patience, stalled = 0;
    while (count != goal && budget-- > 0 && stalled < patience) {
      const std::vector<std::size_t> mobile = movable_indices(c);
      if (mobile.empty()) break;
      const std::size_t i = mobile[uniform_index(rng, mobile.size())];
      CurveStep s = count < goal ? inject(c, i, goal - count, rng) : eject(c, i, count - goal, rng);
      // Where the step at i left the count as it was, the wide form at the same disk.
      if (s.added == 0) {
        const CurveStep w = respread(c, i, count < goal ? 1 : -1, rng);
        if (w.applied) s = w;
      }
      stalled = s.added != 0 ? 0 : stalled + 1;
      count = static_cast<std::size_t>(static_cast<long>(count) + s.added);
      net += s.added;
    }
    return net;
  }

  /// Every curve toward its count at spacing factor_of(c) r, with no even step over
  /// `longest` r (target), each curve's count moving only the way `change` allows, and
  /// by at most `budget` disks over all curves (each curve's change scaled down alike
  /// when they add up to more); then its gaps evened out. Returns the net number of
  /// disks added.
  template <class FactorOf>
  long tune(FactorOf factor_of, Rng& rng, BoundaryChange change = BoundaryChange::any,
            std::size_t budget = static_cast<std::size_t>(-1), double longest = 2) {
    std::vector<long> delta(curves_.size());
    double total = 0;
    for (std::size_t c = 0; c < curves_.size(); ++c) {
      delta[c] = static_cast<long>(target(c, factor_of(c), longest)) - static_cast<long>(movable_count(c));
      if (change == BoundaryChange::only_more) delta[c] = std::max(delta[c], 0L);
      if (change == BoundaryChange::only_fewer) delta[c] = std::min(delta[c], 0L);
      total += static_cast<double>(std::abs(delta[c]));
    }
    const double scale = total > static_cast<double>(budget) ? static_cast<double>(budget) / total : 1.0;
    for (long& d : delta) d = static_cast<long>(static_cast<double>(d) * scale);  // toward zero
    return tune_by(delta, rng);
  }

  /// The boundary's count moved by `change` disks, shared among the curves in proportion
  /// to their lengths (what a curve cannot take is lost: its steps stall).
  long tune_by(long change, Rng& rng) {
    double length = 0;
    for (const Curve<Pos>& cv : curves_) length += cv.length();
    std::vector<long> delta(curves_.size());
    double before = 0;
    for (std::size_t c = 0; c < curves_.size(); ++c) {  // cumulative rounding: the shares add up to change
      const double after = before + curves_[c].length();
      delta[c] = std::lround(static_cast<double>(change) * after / length) - std::lround(static_cast<double>(change) * before / length);
      before = after;
    }
    return tune_by(delta, rng);
  }

  /// Curve c's count moved by delta[c], for every curve; then its gaps evened out.
  long tune_by(const std::vector<long>& delta, Rng& rng) {
    long net = 0;
    for (std::size_t c = 0; c < curves_.size(); ++c) {
      const long goal = std::max(0L, static_cast<long>(movable_count(c)) + delta[c]);
      net += tune_curve(c, static_cast<std::size_t>(goal), rng);
      even_out(c, kEvenSweeps, rng);
    }
    return net;
  }

  /// The wide 1D attractor (delta -1) or repeller (delta +1), the 1D analogue of the
  /// paper's attractor pulling rings of neighbours: the run of consecutive movable disks
  /// i - w .. i + w of curve c (w = 1, 2, 4, ..., clipped to the movable disks) is laid
  /// out again with one disk less (or more), evenly in the measure ds / r(s) between the
  /// two disks that bound it, which stay. The smallest run for which every placed disk
  /// is feasible and the curve stays covered is applied; none: nothing changes.
  CurveStep respread(std::size_t c, std::size_t i, long delta, Rng& rng) {
    const long m = static_cast<long>(disks_[c].size());
    const bool closed = curves_[c].closed;
    if (!movable(c, i) || m + delta < (closed ? 5 : 0)) return {};
    const long j = static_cast<long>(i);
    // The movable run around i: on an open curve, between its first and last movable disk.
    long first = j, last = j;
    if (!closed) {
      while (first > 0 && movable(c, static_cast<std::size_t>(first - 1))) --first;
      while (last + 1 < m && movable(c, static_cast<std::size_t>(last + 1))) ++last;
      if (first == 0 || last == m - 1) return {};  // no bounding disk (no corner disk)
    }
    long prev_lo = j + 1, prev_hi = j - 1;
    for (long w = 1;; w *= 2) {
      long lo = j - w, hi = j + w;
      if (closed) {
        if (hi - lo + 2 > m) lo = j - (m - 2) / 2, hi = lo + m - 2;  // all but one disk
      } else {
        lo = std::max(lo, first), hi = std::min(hi, last);
      }
      if (lo == prev_lo && hi == prev_hi) return {};
      prev_lo = lo, prev_hi = hi;
      if (relay(c, lo, hi, delta, rng)) return {true, delta};
    }
  }

  /// The run of disks lo..hi of curve c (indices; a closed curve's wrap) laid out again
  /// with `delta` disks more or fewer, evenly in ds / r(s) between the two disks that
  /// bound it, which stay. Applied only when every placed disk is feasible and the curve
  /// stays covered, or where none would move (delta 0, every disk within kEvenTol r of
  /// its site); returns whether it was, or none needed to.
  bool relay(std::size_t c, long lo, long hi, long delta, Rng& rng) {
    const long k = hi - lo + 1, k_new = k + delta;
    if (k_new < 0) return false;
    const std::vector<double> at = even_sites(c, arc(c, lo - 1), arc(c, hi + 1), static_cast<std::size_t>(k_new));
    // Already even (as the sampler lays curves out): none moves, as even_out's sweeps skip
    // moves under kEvenTol r. Relaying them anyway cost remesh of fandisk at 10^4
    // vertices a repair around every feature disk, 0.01 s.
    if (delta == 0) {
      bool even = true;
      for (long h = lo; h <= hi && even; ++h)
        even = std::abs(at[static_cast<std::size_t>(h - lo)] - arc(c, h)) <
               kEvenTol * a_.radius_at(point_at_arc(c, at[static_cast<std::size_t>(h - lo)]));
      if (even) return true;
    }
    Plan plan;
    for (long h = lo; h <= hi; ++h) plan.lifted.push_back(disks_[c][index(c, h)].id);
    std::vector<DiskId> run(plan.lifted.begin(), plan.lifted.end());
    for (const double s : at) {
      const Point x = point_at_arc(c, s);
      if (!feasible(A::pos(x), a_.radius_at(x), plan, kNoDisk)) return false;
      plan.placed.push_back({A::pos(x), a_.radius_at(x)});
    }
    std::vector<Ball> balls;
    for (const DiskId id : run) balls.push_back(ball(id));
    if (!balls_covered(balls, plan)) return false;
    // The run's disks keep their order; the middle one goes (or the middle site is new).
    std::vector<DiskId> removed;
    std::vector<std::pair<DiskId, double>> moved;
    std::vector<double> added;
    const std::size_t mid = run.size() / 2;
    if (delta < 0) {
      removed.push_back(run[mid]);
      run.erase(run.begin() + static_cast<long>(mid));
      for (std::size_t h = 0; h < run.size(); ++h) moved.push_back({run[h], at[h]});
    } else {
      for (std::size_t h = 0, g = 0; h < at.size(); ++h) {
        if (h == mid && delta > 0) {
          added.push_back(at[h]);
        } else {
          moved.push_back({run[g++], at[h]});
        }
      }
    }
    apply(c, removed, moved, added, rng);
    return true;
  }

  /// Curve c's gaps evened out, its count kept: all its movable disks laid out evenly at
  /// once where that is valid (sweeps of local moves smooth a long curve only slowly),
  /// else sweeps moving each movable disk to the middle (in ds / r(s)) of its neighbours.
  void even_out(std::size_t c, int sweeps, Rng& rng) {
    const bool closed = curves_[c].closed;
    const long m = static_cast<long>(disks_[c].size());
    if (closed ? m >= 3 : m >= 3 && !movable(c, 0) && !movable(c, static_cast<std::size_t>(m - 1))) {
      if (relay(c, 1, closed ? m - 1 : m - 2, 0, rng)) return;  // a closed curve keeps disk 0 where it is
    }
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      bool any = false;
      for (std::size_t i = 0; i < disks_[c].size(); ++i) {
        if (!movable(c, i) || (closed && disks_[c].size() < 3)) continue;
        const long j = static_cast<long>(i);
        const double s_now = arc(c, j);
        const double s = even_sites(c, arc(c, j - 1), arc(c, j + 1), 1)[0];
        const double r = a_.radius_at(point_at_arc(c, s));
        if (std::abs(s - s_now) < kEvenTol * r) continue;
        const DiskId p = disks_[c][i].id;
        Plan plan;
        plan.lifted.push_back(p);
        const Point x = point_at_arc(c, s);
        if (!feasible(A::pos(x), a_.radius_at(x), plan, kNoDisk)) continue;
        plan.placed.push_back({A::pos(x), a_.radius_at(x)});
        if (!balls_covered({ball(p)}, plan)) continue;
        apply(c, {}, {{p, s}}, {}, rng);
        any = true;
      }
      if (!any) break;
    }
  }

  /// One injection (or ejection) at a movable disk drawn uniformly over all curves.
  CurveStep random_step(bool injection, Rng& rng) {
    std::vector<std::pair<std::size_t, std::size_t>> all;
    for (std::size_t c = 0; c < curves_.size(); ++c)
      for (const std::size_t i : movable_indices(c)) all.push_back({c, i});
    if (all.empty()) return {};
    const auto [c, i] = all[uniform_index(rng, all.size())];
    return injection ? inject(c, i, kMany, rng) : eject(c, i, 1, rng);
  }

  /// 1D injection (paper 2.1 in 1D): lift disk i of curve c, move it to one end (at
  /// random) of its 1D void (the stretch between its neighbours they leave uncovered),
  /// then fill what is left of the void from that end with new disks. Kept when at most
  /// `max_added` disks are added; a pure move (nothing added) is kept too, as in the paper.
  CurveStep inject(std::size_t c, std::size_t i, std::size_t max_added, Rng& rng) {
    const std::size_t m = disks_[c].size();
    if (!movable(c, i) || (curves_[c].closed && m < 3)) return {};
    const long j = static_cast<long>(i);
    const DiskId p = disks_[c][i].id;
    const double sq = arc(c, j - 1), sn = arc(c, j + 1);
    Plan plan;
    plan.lifted = {p};
    auto gaps = arc_gaps(c, sq, sn, plan);
    if (gaps.empty()) return {};
    const bool forward = uniform_index(rng, 2) == 0;
    const std::optional<double> at = first_feasible(c, forward ? gaps.front()[0] : gaps.back()[1],
                                                    forward ? gaps.back()[1] : gaps.front()[0], plan, kNoDisk);
    if (!at) return {};
    std::vector<double> placed_at{*at};
    place(c, *at, plan);
    for (int guard = 0;; ++guard) {
      gaps = arc_gaps(c, sq, sn, plan);
      if (gaps.empty()) break;
      if (guard > 256 || placed_at.size() - 1 >= max_added) return {};
      const auto& g = forward ? gaps.front() : gaps.back();
      const std::optional<double> s = first_feasible(c, forward ? g[0] : g[1], forward ? g[1] : g[0], plan, kNoDisk);
      if (!s) return {};
      placed_at.push_back(*s);
      place(c, *s, plan);
    }
    if (!balls_covered({ball(p)}, plan)) return {};
    apply(c, {}, {{p, placed_at[0]}}, std::vector<double>(placed_at.begin() + 1, placed_at.end()), rng);
    return {true, static_cast<long>(placed_at.size()) - 1};
  }

  /// 1D ejection (the attractor, paper 3.1, in 1D): the two neighbours of disk i along
  /// curve c move toward it as far as they can while their other sides stay covered and
  /// no conflict arises (corner disks stay); if they then cover its stretch, disk i is
  /// removed, else it moves to the middle of what is left of its void (kept only when
  /// that is valid). With max_removed 0 nothing is removed.
  CurveStep eject(std::size_t c, std::size_t i, std::size_t max_removed, Rng& rng) {
    const std::size_t m = disks_[c].size();
    if (!movable(c, i) || (curves_[c].closed && m < 5)) return {};
    const long j = static_cast<long>(i);
    const DiskId p = disks_[c][i].id;
    const double sp = arc(c, j);
    std::vector<std::pair<DiskId, double>> moved;
    Plan plan;  // p stays for now: the neighbours keep their other sides covered with it
    for (const long side : {-1L, 1L}) {
      const std::size_t k = index(c, j + side);
      if (!movable(c, k)) continue;
      const DiskId q = disks_[c][k].id;
      const double from = arc(c, j + side);
      Plan with = plan;
      with.lifted.push_back(q);
      auto ok = [&](double s) {
        Plan trial = with;
        const Point x = point_at_arc(c, s);
        if (!feasible(A::pos(x), a_.radius_at(x), trial, p)) return false;
        trial.placed.push_back({A::pos(x), a_.radius_at(x)});
        return balls_covered({ball(q)}, trial);
      };
      if (!ok(from)) continue;
      double lo = from, hi = sp;
      if (ok(hi)) {
        lo = hi;
      } else {
        for (int it = 0; it < 40; ++it) {
          const double mid = 0.5 * (lo + hi);
          (ok(mid) ? lo : hi) = mid;
        }
      }
      if (lo == from) continue;
      moved.push_back({q, lo});
      plan = with;
      place(c, lo, plan);
    }
    std::vector<Ball> balls{ball(p)};
    for (const auto& [q, s] : moved) balls.push_back(ball(q));
    plan.lifted.push_back(p);
    if (max_removed > 0 && balls_covered(balls, plan)) {
      apply(c, {p}, moved, {}, rng);
      return {true, -1};
    }
    // p stays: at the middle of its void, if that covers it.
    const double sq = moved.size() && moved[0].first == disks_[c][index(c, j - 1)].id ? moved[0].second : arc(c, j - 1);
    const double sn = moved.size() && moved.back().first == disks_[c][index(c, j + 1)].id ? moved.back().second
                                                                                          : arc(c, j + 1);
    const auto gaps = arc_gaps(c, sq, sn, plan);
    if (gaps.empty() || moved.empty()) return {};
    const double mid = 0.5 * (gaps.front()[0] + gaps.back()[1]);
    const Point x = point_at_arc(c, mid);
    if (!feasible(A::pos(x), a_.radius_at(x), plan, kNoDisk)) return {};
    place(c, mid, plan);
    if (!balls_covered(balls, plan)) return {};
    moved.push_back({p, mid});
    apply(c, {}, moved, {}, rng);
    return {true, 0};
  }

 private:
  static constexpr std::size_t kMany = static_cast<std::size_t>(-1) / 2;
  static constexpr double kReach = 0.95;
  static constexpr int kEvenSweeps = 4;
  static constexpr double kEvenTol = 0.02;  // moves shorter than this times r are skipped
  struct Disk {
    double s;
    DiskId id;
  };
  struct Ball {
    Pos c;
    double r;
  };
  // A boundary change being planned: disks lifted from where they are, disks placed.
  struct Plan {
    std::vector<DiskId> lifted;
    std::vector<Ball> placed;
    bool lifts(DiskId id) const { return std::find(lifted.begin(), lifted.end(), id) != lifted.end(); }
  };
  using Gaps = std::vector<std::array<double, 2>>;

  A& a_;
  Pack& packing_;
  std::vector<Curve<Pos>> curves_;
  std::vector<std::vector<Disk>> disks_;  // per curve, by arc length in [0, length)
  double rmax_, tol_, cell_;
  std::map<std::array<std::int64_t, 3>, std::vector<std::array<std::uint32_t, 2>>> cells_;  // pieces per cell

  Ball ball(DiskId id) const { return {packing_.center(id), packing_.radius(id)}; }
  bool fixed(DiskId id) const { return packing_.flags(id) & kFixed; }

  bool movable(std::size_t c, std::size_t i) const {
    if (curves_[c].closed) return true;
    const double s = disks_[c][i].s;
    return s > tol_ && s < curves_[c].length() - tol_;
  }
  std::vector<std::size_t> movable_indices(std::size_t c) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < disks_[c].size(); ++i)
      if (movable(c, i)) out.push_back(i);
    return out;
  }
  // Disk j of curve c for any j (a closed curve wraps), and its unwrapped arc length.
  std::size_t index(std::size_t c, long j) const {
    const long m = static_cast<long>(disks_[c].size());
    return static_cast<std::size_t>(((j % m) + m) % m);
  }
  double arc(std::size_t c, long j) const {
    const long m = static_cast<long>(disks_[c].size());
    const long wraps = (j >= 0 ? j / m : -((-j + m - 1) / m));
    return disks_[c][index(c, j)].s + wraps * curves_[c].length();
  }

  Point point_at_arc(std::size_t c, double s) const {
    const Curve<Pos>& cv = curves_[c];
    const double len = cv.length();
    if (cv.closed) {
      s = std::fmod(s, len);
      if (s < 0) s += len;
    }
    s = std::clamp(s, 0.0, len);
    std::size_t k = static_cast<std::size_t>(std::upper_bound(cv.at.begin(), cv.at.end(), s) - cv.at.begin());
    k = std::min(k == 0 ? 0 : k - 1, cv.pieces() - 1);
    const double t = std::clamp((s - cv.at[k]) / (cv.at[k + 1] - cv.at[k]), 0.0, 1.0);
    return a_.point_at(cv, k, t);
  }

  // n sites strictly inside the arc [from, to] of curve c, cutting it into n + 1 steps
  // of equal measure ds / r(s) (midpoint rule on 16 pieces per step).
  std::vector<double> even_sites(std::size_t c, double from, double to, std::size_t n) const {
    const std::size_t pieces = 16 * (n + 1);
    std::vector<double> cumulative(pieces + 1, 0);
    const double h = (to - from) / static_cast<double>(pieces);
    for (std::size_t k = 0; k < pieces; ++k)
      cumulative[k + 1] = cumulative[k] + h / a_.radius_at(point_at_arc(c, from + h * (static_cast<double>(k) + 0.5)));
    std::vector<double> out;
    for (std::size_t i = 1, k = 0; i <= n; ++i) {
      const double share = cumulative[pieces] * static_cast<double>(i) / static_cast<double>(n + 1);
      while (k + 1 < pieces && cumulative[k + 1] < share) ++k;
      const double f = std::clamp((share - cumulative[k]) / (cumulative[k + 1] - cumulative[k]), 0.0, 1.0);
      out.push_back(from + h * (static_cast<double>(k) + f));
    }
    return out;
  }

  void place(std::size_t c, double s, Plan& plan) const {
    const Point x = point_at_arc(c, s);
    plan.placed.push_back({A::pos(x), a_.radius_at(x)});
  }

  // The fixed disks on curve c, by arc length.
  void find_disks(std::size_t c) {
    const Curve<Pos>& cv = curves_[c];
    std::map<DiskId, double> found;
    for (std::size_t k = 0; k < cv.pieces(); ++k) {
      const Pos a = cv.a(k), d = cv.b(k) - a;
      const double len = norm(d);
      const int chunks = std::max(1, static_cast<int>(std::ceil(len / rmax_)));
      for (int h = 0; h < chunks; ++h) {
        a_.for_each_near(a + d * ((h + 0.5) / chunks), 0.5 * len / chunks + 2 * tol_, [&](DiskId id) {
          if (!fixed(id) || found.count(id)) return;
          const Pos x = packing_.center(id);
          const double t = std::clamp(dot(x - a, d) / (len * len), 0.0, 1.0);
          if (norm(x - (a + d * t)) > tol_) return;
          double s = cv.at[k] + t * len;
          if (cv.closed && s >= cv.length() - tol_) s = 0;
          found[id] = s;
        });
      }
    }
    for (const auto& [id, s] : found) disks_[c].push_back({s, id});
    // An open curve that ends where it starts (a loop through one corner) has its corner
    // disk at both ends.
    if (!cv.closed && norm(cv.v.back() - cv.v.front()) <= tol_) {
      for (const auto& [id, s] : found)
        if (s <= tol_) disks_[c].push_back({cv.length(), id});
    }
    sort_disks(c);
  }
  void sort_disks(std::size_t c) {
    std::sort(disks_[c].begin(), disks_[c].end(),
              [](const Disk& x, const Disk& y) { return x.s < y.s || (x.s == y.s && x.id < y.id); });
  }

  // The pieces of every curve by grid cell: a piece is listed in the 27 cells around
  // each of its samples a quarter cell apart, so a ball of radius <= rmax meets only
  // pieces listed in its center's cell.
  std::array<std::int64_t, 3> cell_of(Pos p) const {
    const auto x = coords(p);
    return {static_cast<std::int64_t>(std::floor(x[0] / cell_)), static_cast<std::int64_t>(std::floor(x[1] / cell_)),
            static_cast<std::int64_t>(std::floor(x[2] / cell_))};
  }
  void index_pieces(std::size_t c) {
    const Curve<Pos>& cv = curves_[c];
    constexpr bool flat = std::is_same_v<Pos, Vec2>;
    for (std::size_t k = 0; k < cv.pieces(); ++k) {
      const Pos a = cv.a(k), d = cv.b(k) - a;
      const int samples = 1 + static_cast<int>(std::ceil(norm(d) / (0.25 * cell_)));
      std::vector<std::array<std::int64_t, 3>> keys;
      for (int h = 0; h <= samples; ++h) {
        const auto key = cell_of(a + d * (static_cast<double>(h) / samples));
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dz = flat ? 0 : -1; dz <= (flat ? 0 : 1); ++dz) keys.push_back({key[0] + dx, key[1] + dy, key[2] + dz});
      }
      std::sort(keys.begin(), keys.end());
      keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
      for (const auto& key : keys)
        cells_[key].push_back({static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(k)});
    }
  }

  // The parameters [t0, t1] of piece k of curve c that no fixed disk covers, in the
  // planned state, within [t0, t1] (disks grown by the tolerance, as everywhere).
  Gaps piece_gaps(std::size_t c, std::size_t k, double t0, double t1, const Plan& plan) const {
    const Curve<Pos>& cv = curves_[c];
    const Pos a = cv.a(k), b = cv.b(k);
    const double len = norm(b - a);
    std::vector<std::array<double, 2>> covered;
    auto add = [&](Pos x, double r) {
      if (const auto in = segment_in_ball(a, b, x, r * (1 + kRelTol))) covered.push_back(*in);
    };
    a_.for_each_near(a + (b - a) * (0.5 * (t0 + t1)), 0.5 * (t1 - t0) * len + rmax_ * (1 + 2 * kRelTol), [&](DiskId id) {
      if (fixed(id) && !plan.lifts(id)) add(packing_.center(id), packing_.radius(id));
    });
    // A placed disk counts with a radius kReach times its own: no step leaves two
    // boundary disks nearly 2r apart, whose circles would meet in a sliver just inside
    // the domain. (With such pairs, planar attractor ejection later left voids there
    // that tune's final check caught: PlanarTuningSteps, TuneDownTo04 - not yet
    // understood; this keeps the boundary out of that case.)
    for (const Ball& x : plan.placed) add(x.c, x.r * kReach);
    std::sort(covered.begin(), covered.end());
    Gaps gaps;
    double t = t0;
    for (const auto& iv : covered) {
      if (iv[1] < t) continue;
      if (iv[0] > t) gaps.push_back({t, std::min(iv[0], t1)});
      t = std::max(t, iv[1]);
      if (t >= t1) break;
    }
    if (t < t1) gaps.push_back({t, t1});
    return gaps;
  }

  // The arc-length intervals of [s0, s1] along curve c (unwrapped) nobody covers.
  Gaps arc_gaps(std::size_t c, double s0, double s1, const Plan& plan) const {
    const Curve<Pos>& cv = curves_[c];
    const double len = cv.length();
    Gaps out;
    double base = cv.closed ? std::floor(s0 / len) * len : 0;
    for (std::size_t k = 0;; ++k) {
      if (k == cv.pieces()) {
        if (!cv.closed) break;
        k = 0, base += len;
      }
      const double from = base + cv.at[k], to = base + cv.at[k + 1];
      if (from >= s1) break;
      if (to <= s0) continue;
      const double piece = to - from;
      const double t0 = std::max(0.0, (s0 - from) / piece), t1 = std::min(1.0, (s1 - from) / piece);
      for (const auto& g : piece_gaps(c, k, t0, t1, plan)) {
        const double g0 = from + g[0] * piece, g1 = from + g[1] * piece;
        if (!out.empty() && g0 - out.back()[1] <= 1e-12 * len) {
          out.back()[1] = g1;
        } else {
          out.push_back({g0, g1});
        }
      }
    }
    return out;
  }

  // True when every curve point in any of `balls` is covered in the planned state.
  bool balls_covered(const std::vector<Ball>& balls, const Plan& plan) const {
    for (const Ball& bl : balls) {
      const auto it = cells_.find(cell_of(bl.c));
      if (it == cells_.end()) continue;
      for (const auto& [c, k] : it->second) {
        const auto in = segment_in_ball(curves_[c].a(k), curves_[c].b(k), bl.c, bl.r * (1 + kRelTol));
        if (in && !piece_gaps(c, k, (*in)[0], (*in)[1], plan).empty()) return false;
      }
    }
    return true;
  }

  // True when a boundary disk (radius r) at x keeps max(r, r_j) from every boundary
  // disk j in the planned state but `also`.
  bool feasible(Pos x, double r, const Plan& plan, DiskId also) const {
    bool bad = false;
    a_.for_each_near(x, std::max(r, rmax_), [&](DiskId id) {
      if (bad || !fixed(id) || id == also || plan.lifts(id)) return;
      bad = is_conflict(squared_norm(packing_.center(id) - x), std::max(r, packing_.radius(id)));
    });
    for (const Ball& b : plan.placed) bad = bad || is_conflict(squared_norm(b.c - x), std::max(r, b.r));
    return !bad;
  }

  // The first feasible arc position from `from` toward `to` (scanned in 64 steps, then
  // refined by bisection), if any.
  std::optional<double> first_feasible(std::size_t c, double from, double to, const Plan& plan, DiskId also) const {
    auto ok = [&](double s) {
      const Point x = point_at_arc(c, s);
      return feasible(A::pos(x), a_.radius_at(x), plan, also);
    };
    if (ok(from)) return from;
    double bad = from;
    for (int h = 1; h <= 64; ++h) {
      double good = from + (to - from) * h / 64;
      if (!ok(good)) {
        bad = good;
        continue;
      }
      for (int it = 0; it < 30; ++it) {
        const double mid = 0.5 * (bad + good);
        (ok(mid) ? good : bad) = mid;
      }
      return good;
    }
    return std::nullopt;
  }

  // Makes a planned change on curve c: removes `removed`, moves `moved` to their arc
  // positions, adds fixed disks at `added`; then interior disks in conflict with a
  // moved or new boundary disk go (it is the latest arrival), and every region a disk
  // left is refilled.
  void apply(std::size_t c, const std::vector<DiskId>& removed, const std::vector<std::pair<DiskId, double>>& moved,
             const std::vector<double>& added, Rng& rng) {
    BasicUndoLog<Pack> log(packing_);
    std::vector<Ball> holes;
    const double len = curves_[c].length();
    auto wrap = [&](double s) {
      if (!curves_[c].closed) return s;
      s = std::fmod(s, len);
      return s < 0 ? s + len : s;
    };
    auto& list = disks_[c];
    for (const DiskId id : removed) {
      holes.push_back(ball(id));
      log.remove(id);
      list.erase(std::find_if(list.begin(), list.end(), [&](const Disk& d) { return d.id == id; }));
    }
    std::vector<DiskId> changed;
    for (const auto& [id, s] : moved) {
      holes.push_back(ball(id));
      log.move(id, point_at_arc(c, s));
      std::find_if(list.begin(), list.end(), [&, id = id](const Disk& d) { return d.id == id; })->s = wrap(s);
      changed.push_back(id);
    }
    for (const double s : added) {
      const Point x = point_at_arc(c, s);
      const DiskId id = log.insert(x, a_.radius_at(x), kFixed);
      list.push_back({wrap(s), id});
      changed.push_back(id);
    }
    sort_disks(c);
    for (const DiskId b : changed) {
      const Pos x = packing_.center(b);
      const double r = packing_.radius(b);
      std::vector<DiskId> doomed;
      a_.for_each_near(x, std::max(r, rmax_), [&](DiskId id) {
        if (!fixed(id) && is_conflict(squared_norm(packing_.center(id) - x), std::max(r, packing_.radius(id))))
          doomed.push_back(id);
      });
      for (const DiskId id : doomed) {
        if (!packing_.alive(id)) continue;  // doomed by an earlier boundary disk too
        holes.push_back(ball(id));
        log.remove(id);
      }
    }
    for (const Ball& h : holes) a_.repair(log, h.c, h.r, rng);
    log.commit();
  }
};

}  // namespace disktune::detail
