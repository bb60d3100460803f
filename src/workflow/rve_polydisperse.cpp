// SPDX-License-Identifier: GPL-3.0-or-later
#include "rve_polydisperse.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string>

#include "disktune/errors.h"
#include "disktune/packing.h"
#include "disktune/voids.h"

namespace disktune::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLargestCv = 0.2;
// Diameters are redrawn beyond this many standard deviations from the mean.
constexpr double kTruncation = 2;
// Growth from equal to unequal diameters in this many steps, each resolved before the next.
constexpr int kGrowthSteps = 5;
// Pushes allowed per fiber, for each growth step and for filling the room left, before
// the fibers count as jammed (a few to 30 are usual).
constexpr std::size_t kPushesPerFiber = 400;
// Rounds of moving fibers into the room left for the smallest fiber (under 10 are usual),
// and how many may pass without fewer corners of room than the fewest yet.
constexpr int kFillRounds = 100;
constexpr int kFillPatience = 20;
// A fiber bounding room moves toward it by this share of the smallest half distance a
// round: far enough to close the room in a few rounds, near enough not to open much behind.
constexpr double kFillStep = 0.125;
// Pairs are pushed this much (relative) beyond their least distance: pushed exactly to
// it, the pushes of the next pairs undo it by ever smaller amounts, hundreds of pushes
// per fiber in a dense packing instead of a few (measured: 1e-3 and five steps both
// faster and less often jammed near the densest fractions than 1e-4 and ten).
constexpr double kPushMargin = 1e-3;

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// The variance of a standard normal variable redrawn beyond +-t: 1 - 2 t phi(t) / (2 Phi(t) - 1).
double truncated_variance(double t) {
  const double density = std::exp(-t * t / 2) / std::sqrt(2 * kPi), mass = std::erf(t / std::sqrt(2.0));
  return 1 - 2 * t * density / mass;
}

// A standard normal variable within +-kTruncation (Box-Muller, then rejection).
double truncated_normal(Rng& rng) {
  for (;;) {
    const double u = 1 - uniform01(rng), v = uniform01(rng);  // u in (0, 1]
    const double z = std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * v);
    if (std::abs(z) <= kTruncation) return z;
  }
}

// The displacement from a to b through the nearest periodic image.
Vec2 nearest_offset(const PeriodicBox& cell, Vec2 a, Vec2 b) {
  const double w = cell.width(), h = cell.height();
  const double dx = b.x - a.x, dy = b.y - a.y;
  return {dx - w * std::round(dx / w), dy - h * std::round(dy / h)};
}

// The fibers as disks of a packing (ids 0..n-1 in order): a grid for neighbour queries
// and, with `radii`, the disks whose voids are the room left.
Packing index_of(const PeriodicBox& cell, const std::vector<Vec2>& centers, const std::vector<double>& radii) {
  Packing index(cell.frame(), *std::max_element(radii.begin(), radii.end()));
  for (std::size_t i = 0; i < centers.size(); ++i) index.insert(centers[i], radii[i]);
  return index;
}

// The distinct fibers other than i whose centers lie within `range` of fiber i's.
void neighbours(const Packing& index, DiskId i, double range, std::vector<DiskId>& out) {
  out.clear();
  index.for_each_near(index.center(i), range, [&](const Neighbor& n) {
    if (n.id != i) out.push_back(n.id);
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// Pushes apart every pair closer than the sum of their half distances `half` (the
// least center distance of i and j is half[i] + half[j]), starting from the fibers in
// `queue`, which must hold one of every such pair. False when that takes more than
// `budget` pushes (which counts them down).
bool push_apart(const PeriodicBox& cell, const std::vector<double>& half, Packing& index,
                std::vector<DiskId> queue, std::size_t& budget, Rng& rng) {
  const double widest = *std::max_element(half.begin(), half.end());
  std::vector<char> queued(half.size(), 0);
  for (const DiskId i : queue) queued[i] = 1;
  std::vector<DiskId> near;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const DiskId i = queue[head];
    queued[i] = 0;
    neighbours(index, i, half[i] + widest, near);
    bool moved = false;
    for (const DiskId j : near) {
      const Vec2 offset = nearest_offset(cell, index.center(i), index.center(j));
      const double need = half[i] + half[j], d = norm(offset);
      // A pair a hair over its distance still goes: moving the cell's origin later
      // rounds the centers.
      if (d >= need * (1 + 1e-12)) continue;
      if (budget-- == 0) return false;
      const double angle = d > 0 ? 0 : 2 * kPi * uniform01(rng);  // coincident centers: any direction
      const Vec2 away = d > 0 ? offset * (1 / d) : Vec2{std::cos(angle), std::sin(angle)};
      const Vec2 step = away * ((need * (1 + kPushMargin) - d) / 2);
      index.move(i, index.center(i) - step);
      index.move(j, index.center(j) + step);
      moved = true;
      if (!queued[j]) queued[j] = 1, queue.push_back(j);
    }
    if (moved && !queued[i]) queued[i] = 1, queue.push_back(i);
  }
  return true;
}

// Moves each fiber bounding room left for the smallest fiber toward that room's corners,
// pushing aside what it meets, until no room is left. False if room is left after
// kFillRounds rounds or kFillPatience rounds without progress, or the fibers jam.
bool fill_room(const PeriodicBox& cell, const std::vector<double>& half, Packing& index, Rng& rng) {
  const double smallest = *std::min_element(half.begin(), half.end());
  std::vector<double> reach(half.size());
  for (std::size_t i = 0; i < half.size(); ++i) reach[i] = half[i] + smallest;
  std::vector<Corner> corners;
  std::vector<DiskId> moved;
  std::size_t budget = kPushesPerFiber * half.size(), fewest = SIZE_MAX;
  for (int round = 0, best = 0; round <= kFillRounds; ++round) {
    std::vector<Vec2> centers(half.size());
    for (std::size_t i = 0; i < half.size(); ++i) centers[i] = index.center(static_cast<DiskId>(i));
    const Packing cover = index_of(cell, centers, reach);
    corners.clear();
    for (DiskId i = 0; i < half.size(); ++i) corners_on_circle(cover, i, corners);
    if (corners.empty()) return true;
    if (corners.size() < fewest) fewest = corners.size(), best = round;
    if (round == kFillRounds || round - best > kFillPatience) return false;
    moved.clear();
    for (const Corner& corner : corners) {
      for (const DiskId f : {corner.a, corner.b}) {
        if (f == kNoDisk) continue;
        const Vec2 toward = nearest_offset(cell, index.center(f), corner.point);
        const double d = norm(toward);
        if (!(d > 0)) continue;
        index.move(f, index.center(f) + toward * (kFillStep * smallest / d));
        moved.push_back(f);
      }
    }
    if (!push_apart(cell, half, index, moved, budget, rng)) return false;
  }
  return false;
}

}  // namespace

DiameterLaw diameter_law(const RveSpec& spec) {
  const double d = spec.diameter, cv = spec.diameter_cv;
  if (!spec.diameter_list.empty()) {
    if (cv != 0) throw InvalidInput("rve: give a list of diameters or a coefficient of variation, not both");
    DiameterLaw law{0, INFINITY, 0, 0};
    for (const double x : spec.diameter_list) {
      if (!(std::isfinite(x) && x > 0)) {
        throw InvalidInput("rve: every diameter in the list must be finite and positive, got " + number(x));
      }
      law.mean += x, law.mean_square += x * x;
      law.smallest = std::min(law.smallest, x), law.largest = std::max(law.largest, x);
    }
    const double n = static_cast<double>(spec.diameter_list.size());
    law.mean /= n, law.mean_square /= n;
    return law;
  }
  if (!(std::isfinite(cv) && cv >= 0 && cv <= kLargestCv)) {
    throw InvalidInput("rve: the diameters' coefficient of variation must lie between 0 and " + number(kLargestCv) +
                       ", got " + number(cv));
  }
  const double spread = cv * kTruncation;
  return {d, d * (1 - spread), d * (1 + spread), d * d * (1 + cv * cv * truncated_variance(kTruncation))};
}

std::vector<double> draw_diameters(const RveSpec& spec, Rng& rng) {
  const auto one = [&] {
    if (!spec.diameter_list.empty()) return spec.diameter_list[uniform_index(rng, spec.diameter_list.size())];
    return spec.diameter * (1 + spec.diameter_cv * truncated_normal(rng));
  };
  std::vector<double> out;
  if (spec.fibers > 0) {
    out.resize(spec.fibers);
    for (double& d : out) d = one();
    return out;
  }
  // Draw until the areas reach the target, then keep the last one only if that comes nearer.
  const double target = spec.fiber_fraction * spec.width * spec.height;
  double sum = 0;
  while (sum < target) {
    out.push_back(one());
    sum += kPi * out.back() * out.back() / 4;
  }
  const double last = kPi * out.back() * out.back() / 4;
  if (out.size() > 1 && sum - target > target - (sum - last)) out.pop_back();
  return out;
}

bool grow_to_diameters(const PeriodicBox& cell, double gap, double equal, const std::vector<double>& diameters,
                       std::vector<Vec2>& centers, Rng& rng) {
  const std::size_t n = centers.size();
  if (n == 0) return true;
  const double start = (equal + gap) / 2;
  std::vector<double> half(n, start);
  // Sized for the largest half distance; the radii are only the grid's.
  std::vector<double> grid_radii(n);
  for (std::size_t i = 0; i < n; ++i) grid_radii[i] = (diameters[i] + gap) / 2;
  Packing index = index_of(cell, centers, grid_radii);
  std::vector<DiskId> all(n);
  std::iota(all.begin(), all.end(), DiskId{0});
  for (int step = 1; step <= kGrowthSteps; ++step) {
    const double t = static_cast<double>(step) / kGrowthSteps;
    for (std::size_t i = 0; i < n; ++i) half[i] = start + t * ((diameters[i] + gap) / 2 - start);
    for (std::size_t i = n; i > 1; --i) std::swap(all[i - 1], all[uniform_index(rng, i)]);
    std::size_t budget = kPushesPerFiber * n;
    if (!push_apart(cell, half, index, all, budget, rng)) return false;
  }
  const bool filled = fill_room(cell, half, index, rng);
  for (std::size_t i = 0; i < n; ++i) centers[i] = index.center(static_cast<DiskId>(i));
  return filled;
}

}  // namespace disktune::detail
