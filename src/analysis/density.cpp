// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/density.h"

#include <cmath>
#include <sstream>

#include "disktune/errors.h"

namespace disktune {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kSqrt3 = 1.73205080756887729353;
}  // namespace

double area_fraction(std::size_t count, double r, double area) {
  return static_cast<double>(count) * kPi * (r / 2) * (r / 2) / area;
}

double relative_radius(std::size_t count, double r, double area) {
  if (count == 0) return 0.0;
  return r / std::sqrt(2 * area / (kSqrt3 * static_cast<double>(count)));
}

double relative_radius_for(double eta) { return std::sqrt(eta * 2 * kSqrt3 / kPi); }

std::size_t count_for_area_fraction(double eta, double r, double area) {
  return static_cast<std::size_t>(std::llround(eta * area / (kPi * (r / 2) * (r / 2))));
}

std::size_t count_for_relative_radius(double rho, double r, double area) {
  // rho^2 = r^2 sqrt(3) N / (2A)  =>  N = 2 A rho^2 / (sqrt(3) r^2)
  return static_cast<std::size_t>(std::llround(2 * area * rho * rho / (kSqrt3 * r * r)));
}

double radius_for_count(std::size_t count, double area, double eta) {
  const double densest = kPi / (2 * kSqrt3);
  if (count == 0 || !(std::isfinite(area) && area > 0) || !(eta > 0 && eta <= densest)) {
    std::ostringstream msg;
    msg << "radius_for_count: needs a count of at least 1 (got " << count << "), a finite positive area (got "
        << area << ") and an area fraction in (0, " << densest << "] (got " << eta << ")";
    throw InvalidInput(msg.str());
  }
  return std::sqrt(4 * area * eta / (kPi * static_cast<double>(count)));
}

}  // namespace disktune
