// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <sstream>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/tuning.h"

namespace disktune {

std::size_t target_count(const Target& target, double r, double area) {
  const double v = target.value;
  auto refuse = [&](const std::string& why) {
    std::ostringstream msg;
    msg << "target " << v << ": " << why;
    throw InvalidInput(msg.str());
  };
  if (!(std::isfinite(v) && v > 0)) refuse("must be a finite positive number");
  std::size_t n = 0;
  switch (target.kind) {
    case Target::Kind::count:
      if (v != std::floor(v)) refuse("a disk count must be a whole number");
      n = static_cast<std::size_t>(v);
      break;
    case Target::Kind::area_fraction:
      if (v >= 0.9069) refuse("area fraction must be below the hexagonal packing's pi/(2 sqrt 3) = 0.9069");
      n = count_for_area_fraction(v, r, area);
      break;
    case Target::Kind::relative_radius:
      if (v >= 1) refuse("relative radius must be below 1 (the hexagonal packing)");
      n = count_for_relative_radius(v, r, area);
      break;
  }
  // No packing of r-separated centers beats the hexagonal density.
  const double densest = 2 * area / (std::sqrt(3.0) * r * r);
  if (static_cast<double>(n) > densest) {
    std::ostringstream msg;
    msg << "more disks than the densest packing holds (" << static_cast<std::size_t>(densest) << ")";
    refuse(msg.str());
  }
  if (n == 0) refuse("means zero disks");
  return n;
}

std::string to_string(Phase phase) {
  switch (phase) {
    case Phase::none: return "none";
    case Phase::void_injection: return "void injection";
    case Phase::repeller_injection: return "repeller injection";
    case Phase::crystal_injection: return "crystal injection";
    case Phase::angle_injection: return "angle injection";
    case Phase::sift_ejection: return "sifted-disks ejection";
    case Phase::attractor_ejection: return "attractor ejection";
    case Phase::crystal_ejection: return "crystal ejection";
  }
  return "?";
}

}  // namespace disktune
