// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers in text files and messages: written in the shortest decimal form that reads
// back to the same double, and read whole.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <ostream>
#include <sstream>
#include <string>
#include <system_error>

namespace disktune::detail {

inline void put_number(std::ostream& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.write(buf, res.ptr - buf);
}

/// The numbers, each as put_number writes it, with `separator` between them.
inline void put_numbers(std::ostream& out, std::initializer_list<double> values,
                        const char* separator) {
  const char* sep = "";
  for (const double v : values) {
    out << sep;
    put_number(out, v);
    sep = separator;
  }
}

/// Three significant digits ("4.5e-07", "0.0141"), for a figure in a message or a
/// description, where every digit (number_text) would only distract.
inline std::string short_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

inline std::string number_text(double v) {
  std::ostringstream out;
  put_number(out, v);
  return out.str();
}

/// The whole of `text` as a finite number, or false.
inline bool parse_number(const std::string& text, double& v) {
  const char* end = text.data() + text.size();
  const auto res = std::from_chars(text.data(), end, v);
  return res.ec == std::errc() && res.ptr == end && std::isfinite(v);
}

/// `s` without leading and trailing blanks (spaces, tabs, line ends).
inline std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace disktune::detail
