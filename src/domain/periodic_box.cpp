// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/periodic_box.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "disktune/errors.h"
#include "radius_limits.h"

namespace disktune {

PeriodicBox::PeriodicBox(double width, double height) {
  if (!(std::isfinite(width) && width > 0 && std::isfinite(height) && height > 0)) {
    std::ostringstream msg;
    msg << "periodic box: width and height must be finite and positive, got " << width << " x "
        << height;
    throw InvalidInput(msg.str());
  }
  frame_ = Frame{{0, 0}, {width, height}, true};
}

Vec2 PeriodicBox::random_point(Rng& rng) const {
  const double x = uniform01(rng) * width();
  const double y = uniform01(rng) * height();
  return wrap({x, y});
}

void PeriodicBox::validate_radius(double r) const {
  std::ostringstream box;
  box << "the " << width() << " x " << height() << " box";
  detail::check_radius_for_area(r, area(), box.str());
  const double side = std::min(width(), height());
  if (!(2 * r < side)) {
    std::ostringstream msg;
    msg << "radius " << r << " is too large for the " << width() << " x " << height()
        << " periodic box: a disk would meet its own periodic image (need 2r < " << side
        << "); use r < " << side / 2 << " or a larger box";
    throw InvalidInput(msg.str());
  }
}

}  // namespace disktune
