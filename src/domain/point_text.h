// SPDX-License-Identifier: GPL-3.0-or-later
// Positions in error messages, with every digit: two corners a rounding apart must not
// print as the same point.
#pragma once

#include <sstream>
#include <string>

#include "../io/number_text.h"
#include "disktune/geometry.h"

namespace disktune::detail {

inline std::string point_text(Vec2 p) {
  std::ostringstream out;
  out << '(';
  put_number(out, p.x);
  out << ", ";
  put_number(out, p.y);
  out << ')';
  return out.str();
}

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
