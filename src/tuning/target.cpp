// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "disktune/errors.h"
#include "disktune/tuning.h"

namespace disktune {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHexFraction = 0.9069;  // pi / (2 sqrt 3), rounded down

// `unit` is the count at area fraction 1: A / (pi r^2 / 4) for one radius, the integral
// of 4 / (pi r(x)^2) over the domain with a sizing; `boundary` what fits along a bounded
// domain's edges (boundary_unit).
std::size_t count_for(const Target& target, double unit, double boundary) {
  const double v = target.value;
  auto refuse = [&](const std::string& why) {
    std::ostringstream msg;
    msg << "target " << v << ": " << why;
    throw InvalidInput(msg.str());
  };
  if (!(std::isfinite(v) && v > 0)) refuse("must be a finite positive number");
  double n = 0;
  switch (target.kind) {
    case Target::Kind::count:
      if (v != std::floor(v)) refuse("a disk count must be a whole number");
      n = v;
      break;
    case Target::Kind::area_fraction:
      if (v >= kHexFraction) refuse("area fraction must be below the hexagonal packing's pi/(2 sqrt 3) = 0.9069");
      n = std::round(v * unit);
      break;
    case Target::Kind::relative_radius:  // eta = pi / (2 sqrt 3) rho^2
      if (v >= 1) refuse("relative radius must be below 1 (the hexagonal packing)");
      n = std::round(kPi / (2 * std::sqrt(3.0)) * v * v * unit);
      break;
  }
  // No packing of r-separated centers beats the hexagonal density, but in a bounded
  // domain those on the boundary have half their disk outside: a thin domain holds a
  // row of disks whose area exceeds its own.
  const double densest = kPi / (2 * std::sqrt(3.0)) * unit + boundary;
  if (n > densest) {
    std::ostringstream msg;
    msg << "more disks than the densest packing holds (" << static_cast<std::size_t>(densest);
    if (boundary > 0) msg << ": the hexagonal packing's density over the area, and a row of disks along the boundary";
    msg << ")";
    refuse(msg.str());
  }
  if (n < 1) refuse("means zero disks");
  return static_cast<std::size_t>(n);
}

}  // namespace

std::size_t target_count_for_unit(const Target& target, double unit, double boundary) {
  return count_for(target, unit, boundary);
}

std::size_t target_count(const Target& target, double r, double area) {
  return count_for(target, 4 * area / (kPi * r * r), 0);
}

std::size_t target_count(const Target& target, const Packing& packing, double area) {
  return count_for(target, density_unit(packing, area), boundary_unit(packing));
}

std::string to_string(Phase phase) {
  switch (phase) {
    case Phase::none: return "none";
    case Phase::void_injection: return "void injection";
    case Phase::repeller_injection: return "repeller injection";
    case Phase::crystal_injection: return "crystal injection";
    case Phase::grain_injection:
      return "grain injection";
    case Phase::squeeze_injection:
      return "squeeze injection";
    case Phase::angle_injection: return "angle injection";
    case Phase::sift_ejection: return "sifted-disks ejection";
    case Phase::attractor_ejection: return "attractor ejection";
    case Phase::crystal_ejection: return "crystal ejection";
    case Phase::boundary_injection: return "boundary injection";
    case Phase::boundary_ejection: return "boundary ejection";
    case Phase::relaxation: return "relaxation";
  }
  return "?";
}

Method method_named(const std::string& name) {
  static const std::pair<const char*, Method> kNames[] = {
      {"auto", Method::automatic},
      {"void", Method::void_injection},
      {"repeller", Method::repeller_injection},
      {"crystal", Method::crystal_injection},
      {"grains", Method::grain_injection},
      {"squeeze", Method::squeeze_injection},
      {"angle", Method::angle_injection},
      {"sift", Method::sift_ejection},
      {"attractor", Method::attractor_ejection},
      {"crystal-eject", Method::crystal_ejection}};
  for (const auto& [known, method] : kNames)
    if (name == known) return method;
  throw InvalidInput(
      "method '" + name +
      "': give auto, void, repeller, crystal, grains, squeeze, angle, sift, attractor or "
      "crystal-eject");
}

}  // namespace disktune
