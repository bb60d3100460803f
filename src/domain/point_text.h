// SPDX-License-Identifier: GPL-3.0-or-later
// Positions in error messages, with every digit: two corners a rounding apart must not
// print as the same point.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <sstream>
#include <string>

#include "../io/number_text.h"
#include "disktune/geometry.h"
#include "disktune/vec3.h"

namespace disktune::detail {

/// "(0.1, 0.2)": the coordinates in parentheses, comma-separated.
inline std::string coordinates_text(std::initializer_list<double> coordinates) {
  std::ostringstream out;
  out << '(';
  put_numbers(out, coordinates, ", ");
  out << ')';
  return out.str();
}

inline std::string point_text(Vec2 p) { return coordinates_text({p.x, p.y}); }
inline std::string point_text(Vec3 p) { return coordinates_text({p.x, p.y, p.z}); }

/// "loop 0 (the outer boundary)" or "loop 2 (hole 1)".
inline std::string loop_text(std::size_t loop) {
  std::ostringstream out;
  out << "loop " << loop;
  if (loop == 0) {
    out << " (the outer boundary)";
  } else {
    out << " (hole " << loop - 1 << ')';
  }
  return out.str();
}

}  // namespace disktune::detail
