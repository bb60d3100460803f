// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a small text format line by line (internal): non-empty lines split into
// words, '#' comments removed, numbers parsed whole, and errors that name the file and
// the line. Shared by the .poly reader and the sizing grid reader.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

#include "disktune/errors.h"

namespace disktune::detail {

class WordLines {
 public:
  WordLines(std::istream& in, std::string path) : in_(in), path_(std::move(path)) {}

  /// The next line with words; false at the end of the file.
  bool next(std::vector<std::string>& words) {
    std::string text;
    while (std::getline(in_, text)) {
      ++line_;
      text = text.substr(0, text.find('#'));
      std::istringstream split(text);
      words.clear();
      for (std::string w; split >> w;) words.push_back(w);
      if (!words.empty()) return true;
    }
    return false;
  }

  /// `what`, if given, names the value in the message ("nx", "a radius").
  long long integer(const std::string& word, const std::string& what = "") const {
    long long v = 0;
    const auto res = std::from_chars(word.data(), word.data() + word.size(), v);
    if (res.ec != std::errc() || res.ptr != word.data() + word.size()) {
      fail("expected " + named(what) + "a whole number, got '" + word + "'");
    }
    return v;
  }

  double number(const std::string& word, const std::string& what = "") const {
    double v = 0;
    const auto res = std::from_chars(word.data(), word.data() + word.size(), v);
    if (res.ec != std::errc() || res.ptr != word.data() + word.size() || !std::isfinite(v)) {
      fail("expected " + named(what) + "a finite number, got '" + word + "'");
    }
    return v;
  }

  /// Throws InvalidInput "PATH, line N: what" (the current line unless one is given).
  [[noreturn]] void fail(const std::string& what, std::size_t line = 0) const {
    std::ostringstream msg;
    msg << path_ << ", line " << (line ? line : line_) << ": " << what;
    throw InvalidInput(msg.str());
  }

  std::size_t line() const { return line_; }

 private:
  static std::string named(const std::string& what) { return what.empty() ? "" : what + ", "; }

  std::istream& in_;
  std::string path_;
  std::size_t line_ = 0;
};

}  // namespace disktune::detail
