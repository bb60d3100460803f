// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/packing.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

#include "disktune/errors.h"
#include "../domain/precision.h"

namespace disktune {

// Cells of a diagonal just below r_max hold one disk each in a uniform packing.
namespace {

// Checked before the grid is sized from it.
const Frame& checked(const Frame& frame, double max_radius) {
  const double reach = std::max({std::abs(frame.origin.x), std::abs(frame.origin.y),
                                 std::abs(frame.origin.x + frame.extent.x), std::abs(frame.origin.y + frame.extent.y)});
  detail::check_coordinates_for_radius(reach, max_radius);
  return frame;
}

}  // namespace

Packing::Packing(const Frame& frame, double max_radius)
    : grid_(checked(frame, max_radius), max_radius * 0.70710678118654752 * (1 - 1e-6)), max_radius_(max_radius) {}

DiskId Packing::insert(Vec2 center, double radius, std::uint8_t flags) {
  assert(radius > 0 && radius <= max_radius_);
  center = frame().wrap(center);
  DiskId id;
  if (!free_ids_.empty()) {
    id = free_ids_.back();
    free_ids_.pop_back();
    center_[id] = center;
    radius_[id] = radius;
    flags_[id] = flags;
  } else {
    id = static_cast<DiskId>(radius_.size());
    center_.push_back(center);
    radius_.push_back(radius);
    flags_.push_back(flags);
  }
  grid_.insert(id, center, radius);
  ++live_;
  return id;
}

void Packing::remove(DiskId id) {
  assert(alive(id));
  grid_.remove(id, center_[id]);
  radius_[id] = 0;
  flags_[id] = 0;
  free_ids_.push_back(id);
  --live_;
}

void Packing::move(DiskId id, Vec2 center) {
  assert(alive(id));
  if (sizing_) radius_[id] = radius_at(center);
  center = frame().wrap(center);
  grid_.remove(id, center_[id]);
  center_[id] = center;
  grid_.insert(id, center, radius_[id]);
}

double Packing::sized_radius(Vec2 q) const {
  const Vec2 x = frame().wrap(q);
  const double r = (*sizing_)(x);
  if (!(r > 0 && r <= max_radius_)) {
    std::ostringstream msg;
    msg << "the sizing " << sizing_->description() << " gives r = " << r << " at (" << x.x << ", "
        << x.y << "), outside (0, " << max_radius_ << "], the range it was sampled in";
    throw InvalidInput(msg.str());
  }
  return r;
}

std::vector<DiskId> Packing::ids() const {
  std::vector<DiskId> out;
  out.reserve(live_);
  for (DiskId id = 0; id < id_bound(); ++id) {
    if (alive(id)) out.push_back(id);
  }
  return out;
}

bool Packing::conflicts(Vec2 q, DiskId ignore) const {
  return !inside(q) || any_near(q, max_radius_, [&](const Neighbor& n) {
    return n.id != ignore && is_conflict(n.d2, n.radius);
  });
}

bool Packing::covered(Vec2 q, DiskId ignore) const {
  return any_near(q, max_radius_ * (1 + kRelTol), [&](const Neighbor& n) {
    return n.id != ignore && is_covered(n.d2, n.radius);
  });
}

double density_unit(const Packing& packing, double area) {
  constexpr double kPi = 3.14159265358979323846;
  if (!packing.sizing()) return 4 * area / (kPi * packing.max_radius() * packing.max_radius());
  return density_integral(*packing.sizing(), packing.frame(), packing.domain());
}

double boundary_unit(const PlanarDomain& domain, const Sizing* sizing, double r) {
  double unit = 0;
  for (const BoundarySegment& s : domain.segments()) {
    const double len = distance(s.a, s.b);
    if (!sizing) {
      unit += len / r;
      continue;
    }
    for (double t = 0; t < len;) {  // midpoint rule, steps a quarter of r at their start
      const double h = std::min(0.25 * (*sizing)(s.a + (s.b - s.a) * (t / len)), len - t);
      unit += h / (*sizing)(s.a + (s.b - s.a) * ((t + h / 2) / len));
      t += h;
    }
  }
  return unit;
}

double boundary_unit(const Packing& packing) {
  if (!packing.domain()) return 0;
  return boundary_unit(*packing.domain(), packing.sizing(), packing.max_radius());
}

}  // namespace disktune
