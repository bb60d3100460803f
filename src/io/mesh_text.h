// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to polygon_soup.cpp: what the mesh file readers share. The file is in memory
// whole; MeshText walks its text counting lines, numbers are parsed whole, counts are
// checked against the bytes left before anything is allocated, and messages name the
// file and the place but never echo binary garbage (excerpt).
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "disktune/errors.h"

namespace disktune::detail {

/// At most 20 characters of `text` fit for a message: printable ASCII as is, any other
/// byte as \xNN, "..." when cut.
inline std::string excerpt(std::string_view text) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < 20; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (text.size() > 20) out += "...";
  return out;
}

inline std::string in_quotes(std::string_view text) { return "'" + excerpt(text) + "'"; }

/// Separators within a line; '\r' too, so CRLF files read as LF files.
inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// `line` up to its first '#'.
inline std::string_view before_comment(std::string_view line) {
  return line.substr(0, line.find('#'));
}

inline std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (is_blank(line[i]) || line[i] == '\n')) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i]) && line[i] != '\n') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

// Numbers are whole words. A leading '+' is accepted, as operator>> (CGAL's readers)
// accepts it; "nan" and "inf" parse, and the readers refuse them with their own message.
template <class T>
bool parse_whole(std::string_view w, T& v) {
  if (!w.empty() && w[0] == '+') {
    w.remove_prefix(1);
    if (!w.empty() && (w[0] == '+' || w[0] == '-')) return false;
  }
  const auto res = std::from_chars(w.data(), w.data() + w.size(), v);
  return res.ec == std::errc() && res.ptr == w.data() + w.size() && !w.empty();
}

inline bool parse_double(std::string_view w, double& v) { return parse_whole(w, v); }
inline bool parse_float(std::string_view w, float& v) { return parse_whole(w, v); }
inline bool parse_integer(std::string_view w, long long& v) { return parse_whole(w, v); }

/// A whole number, also written as an integral decimal ("3.0"), as CGAL's OFF reader,
/// which reads face lines as doubles, accepts it.
inline bool parse_index(std::string_view w, long long& v) {
  if (parse_integer(w, v)) return true;
  double d = 0;
  if (!parse_double(w, d) || !(std::abs(d) < 9007199254740992.0) || d != std::floor(d))
    return false;
  v = static_cast<long long>(d);
  return true;
}

/// "3 vertices (0 to 2)" or "no vertices": what a face's index must stay under.
inline std::string vertex_range(std::uint64_t n) {
  if (n == 0) return "no vertices";
  return std::to_string(n) + " vertices (0 to " + std::to_string(n - 1) + ")";
}

/// acc + count * each, or the largest value when that overflows.
inline std::uint64_t add_product(std::uint64_t acc, std::uint64_t count, std::uint64_t each) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  if (each != 0 && count > (kMax - acc) / each) return kMax;
  return acc + count * each;
}

/// A cursor over a text file (or the text part of one) that counts lines.
class MeshText {
 public:
  /// Starts at byte `start`, on line `line`; a UTF-8 byte order mark at the start of the
  /// file is skipped.
  MeshText(const std::string& path, std::string_view text, std::size_t start = 0,
           std::size_t line = 1)
      : path_(path), text_(text), pos_(start), line_(line) {
    if (pos_ == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  bool at_end() const { return pos_ >= text_.size(); }
  std::size_t line() const { return line_; }
  std::size_t position() const { return pos_; }
  std::size_t bytes_left() const { return at_end() ? 0 : text_.size() - pos_; }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  const std::string& path() const { return path_; }

  /// Skips blanks and line ends.
  void skip_space() {
    while (!at_end() && (is_blank(text_[pos_]) || text_[pos_] == '\n')) advance();
  }

  /// Skips blanks, line ends and '#' comments (to the end of their line).
  void skip_space_and_comments() {
    for (skip_space(); peek() == '#'; skip_space()) {
      while (!at_end() && text_[pos_] != '\n') ++pos_;
    }
  }

  /// The next word (after blanks and line ends); empty at the end of the text.
  std::string_view word() {
    skip_space();
    const std::size_t start = pos_;
    while (!at_end() && !is_blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }

  /// The letters and digits from here on (possibly none).
  std::string_view alnum_word() {
    const std::size_t start = pos_;
    while (!at_end() && is_alnum(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  /// The rest of the current line without its line end, which is passed.
  std::string_view line_rest() {
    const std::size_t start = pos_;
    while (!at_end() && text_[pos_] != '\n') ++pos_;
    const std::string_view rest = text_.substr(start, pos_ - start);
    if (!at_end()) advance();
    return rest;
  }

  /// Throws InvalidInput "PATH, line N: what" (the current line unless one is given).
  [[noreturn]] void fail(const std::string& what, std::size_t line = 0) const {
    throw InvalidInput(path_ + ", line " + std::to_string(line ? line : line_) + ": " + what);
  }

 private:
  static bool is_alnum(char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  }
  void advance() {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }

  std::string path_;
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_;
};

}  // namespace disktune::detail
