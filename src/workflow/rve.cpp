// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/rve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "../geometry/threads.h"
#include "../io/number_text.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/resources.h"
#include "disktune/sampling.h"
#include "rve_polydisperse.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The densest packing of equal disks, hexagonal: pi / (2 sqrt 3).
const double kHexagonal = kPi / (2 * std::sqrt(3.0));

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

double fiber_area(double d) { return kPi * d * d / 4; }

// Tries at growing unequal fibers from one arrangement of equal ones.
constexpr int kGrowthAttempts = 3;

bool unequal(const RveSpec& spec) { return spec.diameter_cv != 0 || !spec.diameter_list.empty(); }

}  // namespace

std::size_t rve_fiber_count(const RveSpec& spec) {
  const double g = spec.gap;
  const detail::DiameterLaw law = detail::diameter_law(spec);
  const double d = law.mean;
  if (!(std::isfinite(d) && d > 0)) throw InvalidInput("rve: the fiber diameter must be finite and positive, got " + number(d));
  if (!(std::isfinite(g) && g >= 0)) {
    throw InvalidInput("rve: the gap between fibers must be finite and 0 or more, got " + number(g));
  }
  const PeriodicBox cell(spec.width, spec.height);
  if (!(law.largest + g < 0.5 * std::min(cell.width(), cell.height()))) {
    throw InvalidInput("rve: fibers of diameter " + number(law.largest) + " with gap " + number(g) +
                       " are too wide for the " + number(cell.width()) + " x " + number(cell.height()) +
                       " cell: diameter + gap must be under half its smaller side; make the cell larger or "
                       "the fibers smaller");
  }
  const bool by_count = spec.fibers > 0, by_fraction = spec.fiber_fraction != 0;
  if (by_count == by_fraction) {
    throw InvalidInput(by_count ? "rve: give a fiber count or a fiber volume fraction, not both"
                                : "rve: give a fiber count or a fiber volume fraction");
  }
  if (by_fraction && !(spec.fiber_fraction > 0 && spec.fiber_fraction < 1)) {
    throw InvalidInput("rve: the fiber volume fraction must lie between 0 and 1, got " + number(spec.fiber_fraction));
  }
  // Unequal fibers count in their mean area, the area of the root mean square diameter.
  const double rms = unequal(spec) ? std::sqrt(law.mean_square) : d;
  const double area = cell.area(), one = fiber_area(rms);
  const double wanted = by_count ? static_cast<double>(spec.fibers) : std::round(spec.fiber_fraction * area / one);
  if (wanted < 1) {
    throw InvalidInput("rve: a fiber volume fraction of " + number(spec.fiber_fraction) + " is less than half a fiber (" +
                       number(one / area) + " each) in this cell; ask for more, or make the cell larger");
  }
  if (!(wanted <= 1e15)) {  // also infinite: a cell of 1e300 squared
    throw InvalidInput("rve: " + (std::isfinite(wanted) ? number(wanted) + " fibers are" : std::string("that is")) +
                       " far too many fibers; ask for fewer, make the fibers larger or the cell smaller");
  }
  // The hexagonal packing at center distance D + g holds the most.
  const double spacing_share = rms / (rms + g);
  const double most = kHexagonal * spacing_share * spacing_share;
  if (wanted * one / area > most) {
    throw InvalidInput("rve: " + number(wanted) + " fibers (vf " + number(wanted * one / area) +
                       ") do not fit: with gap " + number(g) + " the densest (hexagonal) arrangement reaches vf " +
                       number(most) + "; ask for fewer fibers or a smaller gap");
  }
  return static_cast<std::size_t>(wanted);
}

namespace {

// The memory check of `parallel` arrangements made at once.
void check_memory(const RveSpec& spec, std::size_t count, std::size_t parallel) {
  const double r = std::sqrt(detail::diameter_law(spec).mean_square) + spec.gap;
  const ResourceEstimate need = estimate_resources(PeriodicBox(spec.width, spec.height), r).tuned_to(static_cast<double>(count));
  const double limit = (spec.max_memory > 0 ? spec.max_memory : available_memory()) / static_cast<double>(parallel);
  if (need.bytes > limit) {  // in fibers, not in the radius the packing counts in
    const double fits = std::floor(0.9 * static_cast<double>(count) * limit / need.bytes);
    throw InvalidInput("rve: " + std::to_string(count) + " fibers need about " + detail::short_text(need.bytes / 1073741824.0) +
                           " GiB" + (parallel > 1 ? " per realization (" + std::to_string(parallel) + " at once)" : "") +
                           " but " + detail::short_text(limit * static_cast<double>(parallel) / 1073741824.0) +
                           " GiB are allowed; ask for at most about " + std::to_string(static_cast<std::size_t>(fits)) +
                           " fibers (larger fibers or a smaller cell)" + (parallel > 1 ? ", fewer threads" : "") +
                           ", or allow more memory",
                       InvalidInput::Remedy::memory);
  }
  check_resources(need, limit);
}

// A place for a cell side, and how far it keeps from the fibers' tangent lines.
struct SidePlace {
  double clearance, at;
};

// The places in [0, period) for a cell side that keep farthest from every fiber's
// tangent lines c - d/2 and c + d/2 (`coords` the centers' coordinates across the
// side), widest first: the middles of the `count` widest gaps between those lines.
// Where a fiber boundary nearly touches a side, a finite-element mesh needs slivers.
std::vector<SidePlace> side_places(const std::vector<double>& coords, const std::vector<double>& diameters,
                                   double period, std::size_t count) {
  std::vector<double> marks;
  marks.reserve(2 * coords.size());
  for (std::size_t i = 0; i < coords.size(); ++i) {
    const double c = coords[i], radius = diameters[i] / 2;
    for (const double m : {c - radius, c + radius}) marks.push_back(m - period * std::floor(m / period));
  }
  std::sort(marks.begin(), marks.end());
  std::vector<SidePlace> places;
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const double from = i == 0 ? marks.back() - period : marks[i - 1], gap = marks[i] - from;
    const double at = from + gap / 2;
    places.push_back({gap / 2, at < 0 ? at + period : at});
  }
  count = std::min(count, places.size());
  std::partial_sort(places.begin(), places.begin() + static_cast<std::ptrdiff_t>(count), places.end(),
                    [](const SidePlace& a, const SidePlace& b) { return a.clearance > b.clearance; });
  places.resize(count);
  return places;
}

// How far the corner `at` keeps from every fiber boundary (a fiber boundary passing a
// hair from a corner cuts slivers off both sides).
double corner_clearance(const Rve& rve, Vec2 at) {
  const double w = rve.cell.width(), h = rve.cell.height();
  double least = INFINITY;
  for (std::size_t i = 0; i < rve.centers.size(); ++i) {
    const Vec2 c = rve.centers[i];
    const double dx = c.x - at.x - w * std::round((c.x - at.x) / w), dy = c.y - at.y - h * std::round((c.y - at.y) / h);
    least = std::min(least, std::abs(std::hypot(dx, dy) - rve.diameters[i] / 2));
  }
  return least;
}

// Translates the arrangement (still periodic, as random as before) so that the cell's
// sides and corners keep clear of the fiber boundaries: of the places the widest gaps
// give each side, the pair whose worst clearance, sides and corner, is largest.
void clear_sides(Rve& rve) {
  constexpr std::size_t kCandidates = 8;
  std::vector<double> xs, ys;
  for (const Vec2& c : rve.centers) xs.push_back(c.x), ys.push_back(c.y);
  Vec2 shift{0, 0};
  double best = -1;
  for (const SidePlace& x : side_places(xs, rve.diameters, rve.cell.width(), kCandidates)) {
    for (const SidePlace& y : side_places(ys, rve.diameters, rve.cell.height(), kCandidates)) {
      const double worst = std::min(std::min(x.clearance, y.clearance), corner_clearance(rve, {x.at, y.at}));
      if (worst > best) best = worst, shift = {x.at, y.at};
    }
  }
  for (Vec2& c : rve.centers) c = rve.cell.wrap(c - shift);
}

// `count` equal fibers of diameter spec.diameter.
Rve make_equal(const RveSpec& spec, std::size_t count) {
  Rve out;
  out.cell = PeriodicBox(spec.width, spec.height);
  out.diameter = spec.diameter;
  out.gap = spec.gap;
  const double r = spec.diameter + spec.gap;  // centers at least this far apart
  Rng rng(spec.seed);
  Packing packing = sample_mps(out.cell, r, rng);
  for (const DiskId id : packing.ids()) out.sample_centers.push_back(packing.center(id));
  out.sample_diameter = spec.diameter;
  out.tuning = tune(packing, out.cell, Target::count(count), rng, spec.tune);
  out.centers.reserve(packing.size());
  for (const DiskId id : packing.ids()) out.centers.push_back(packing.center(id));
  out.diameters.assign(out.centers.size(), spec.diameter);
  out.fiber_fraction = static_cast<double>(packing.size()) * fiber_area(spec.diameter) / out.cell.area();
  out.packing_fraction = area_fraction(packing.size(), r, out.cell.area());
  return out;
}

// Unequal fibers: the diameters drawn (from their own stream of the seed), equal fibers
// of their mean square diameter tuned to their count, then grown to them.
Rve make_unequal(const RveSpec& spec) {
  Rng rng(spec.seed ^ 0x5bd1e9955bd1e995ULL);
  std::vector<double> diameters = detail::draw_diameters(spec, rng);
  const auto n = static_cast<double>(diameters.size());
  double sum = 0, sum_square = 0, fibers = 0, disks = 0;
  for (const double d : diameters) sum += d, sum_square += d * d, fibers += fiber_area(d), disks += fiber_area(d + spec.gap);
  RveSpec equal = spec;
  equal.diameter = std::sqrt(sum_square / n), equal.diameter_cv = 0, equal.diameter_list.clear();
  equal.fibers = diameters.size(), equal.fiber_fraction = 0;
  rve_fiber_count(equal);  // the diameters drawn may fit worse than their law
  Rve out = make_equal(equal, diameters.size());
  const std::string asked = std::to_string(diameters.size()) + " fibers (vf " + number(fibers / out.cell.area()) + ")";
  if (!out.tuning.reached) {
    const bool dense = out.centers.size() < diameters.size();
    throw InvalidInput("rve: " + asked + " were asked for, but equal fibers of their mean size " +
                       (dense ? "stop at " : "stay at ") + std::to_string(out.centers.size()) +
                       (dense ? ": ask for a lower fiber fraction or a smaller gap"
                              : ": fewer leave room for more; ask for a higher fiber fraction"));
  }
  // Another order of the diameters over the same places often succeeds where one failed.
  const std::vector<Vec2> places = out.centers;
  bool grown = false;
  for (int attempt = 0; attempt < kGrowthAttempts && !grown; ++attempt) {
    if (attempt > 0) {
      out.centers = places;
      for (std::size_t i = diameters.size(); i > 1; --i) std::swap(diameters[i - 1], diameters[uniform_index(rng, i)]);
    }
    grown = detail::grow_to_diameters(out.cell, spec.gap, equal.diameter, diameters, out.centers, rng);
  }
  if (!grown) {
    throw InvalidInput("rve: " + asked + " of diameters spread by " + number(std::sqrt(sum_square / n - sum * sum / n / n) / (sum / n)) +
                       " (coefficient of variation) could not be arranged without overlap and without room for one more of "
                       "the smallest; ask for a lower fiber fraction, a smaller gap or spread, or try another seed");
  }
  out.diameter = sum / n;
  out.diameters = diameters;
  out.fiber_fraction = fibers / out.cell.area();
  out.packing_fraction = disks / out.cell.area();
  return out;
}

Rve make_checked(const RveSpec& spec, std::size_t count) {
  Rve out = unequal(spec) ? make_unequal(spec) : make_equal(spec, count);
  clear_sides(out);
  return out;
}

}  // namespace

Rve make_rve(const RveSpec& spec) {
  const std::size_t count = rve_fiber_count(spec);
  check_memory(spec, count, 1);
  return make_checked(spec, count);
}

std::vector<Rve> make_rves(const RveSpec& spec, std::size_t count, unsigned threads) {
  const std::size_t fibers = rve_fiber_count(spec);
  threads = detail::thread_count(threads);
  if (count == 0) return {};
  check_memory(spec, fibers, std::min<std::size_t>(threads, count));
  std::vector<Rve> out(count);
  // A failure stops the handing out (the others finish their current one); of those that
  // failed, the first by index is reported, not the first in time.
  std::vector<std::exception_ptr> failed(count);
  try {
    detail::parallel_for(count, threads, [&](std::size_t k, unsigned) {
      try {
        RveSpec one = spec;
        one.seed = spec.seed + k;
        out[k] = make_checked(one, fibers);
      } catch (...) {
        failed[k] = std::current_exception();
        throw;
      }
    });
  } catch (...) {
    if (std::none_of(failed.begin(), failed.end(),
                     [](const std::exception_ptr& e) { return e != nullptr; }))
      throw;  // not a realization's own failure
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace disktune
