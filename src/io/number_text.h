// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers in text files: the shortest decimal form that reads back to the same double.
#pragma once

#include <charconv>
#include <ostream>

namespace disktune::detail {

inline void put_number(std::ostream& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.write(buf, res.ptr - buf);
}

}  // namespace disktune::detail
