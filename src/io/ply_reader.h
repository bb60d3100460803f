// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to polygon_soup.cpp: the PLY reader (ascii, binary_little_endian,
// binary_big_endian). The points are the x, y, z of the elements "vertex" (or
// "vertices"), any numeric type; the polygons the list "vertex_indices" (or
// "vertex_index") of the elements "face" (or "faces"), any integer types; every other
// element and property is read past. Values read as CGAL 5.5 reads them (a float is read
// as a float, then widened), so valid files give the same soup. The header is checked
// whole before any data is read (CGAL crashed on a property before any element and read
// past unknown types), and the counts against the bytes left before anything is
// allocated; coordinates must be finite and faces have 3 or more corners in range.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_text.h"
#include "polygon_soup.h"

namespace disktune::detail {

namespace ply {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct TypeInfo {
  const char* name;  // the classic name; the sized one is an alias
  const char* sized;
  Type type;
  std::size_t bytes;
  bool integer;
  double low, high;  // the range of an integer type
};

inline const TypeInfo* type_info(std::string_view name) {
  static const TypeInfo types[] = {
      {"char", "int8", Type::Int8, 1, true, -128, 127},
      {"uchar", "uint8", Type::UInt8, 1, true, 0, 255},
      {"short", "int16", Type::Int16, 2, true, -32768, 32767},
      {"ushort", "uint16", Type::UInt16, 2, true, 0, 65535},
      {"int", "int32", Type::Int32, 4, true, -2147483648.0, 2147483647.0},
      {"uint", "uint32", Type::UInt32, 4, true, 0, 4294967295.0},
      {"float", "float32", Type::Float32, 4, false, 0, 0},
      {"double", "float64", Type::Float64, 8, false, 0, 0},
  };
  for (const TypeInfo& t : types) {
    if (name == t.name || name == t.sized) return &t;
  }
  return nullptr;
}

struct Property {
  std::string name;
  const TypeInfo* type = nullptr;   // of the value, or of a list's entries
  const TypeInfo* count = nullptr;  // of a list's length; null for a single value
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;
  std::vector<Property> properties;
  int find(std::string_view n) const {
    for (std::size_t k = 0; k < properties.size(); ++k) {
      if (properties[k].name == n) return static_cast<int>(k);
    }
    return -1;
  }
};

// The values of an ascii body: words, read as CGAL reads them (a float as a float).
class AsciiValues {
 public:
  AsciiValues(const std::string& path, std::string_view bytes, std::size_t start, std::size_t line)
      : in_(path, bytes, start, line), last_line_(line) {}
  std::uint64_t bytes_left() const { return in_.bytes_left(); }
  // n list entries take at least 2n - 1 bytes (a digit and a separator each).
  std::uint64_t max_entries(const TypeInfo&) const { return (in_.bytes_left() + 1) / 2; }
  double value(const TypeInfo& t, const std::string& item) {
    const std::string_view w = in_.word();
    if (w.empty()) {
      in_.fail("the file ends in " + item + "; it is truncated or a count is wrong", last_line_);
    }
    last_line_ = in_.line();
    double v = 0;
    bool ok = false;
    if (t.type == Type::Float32) {
      float f = 0;
      ok = parse_float(w, f);
      v = f;
    } else if (t.type == Type::Float64) {
      ok = parse_double(w, v);
    } else {
      long long i = 0;
      ok = parse_integer(w, i) && i >= t.low && i <= t.high;
      v = static_cast<double>(i);
    }
    if (!ok) fail(item + ": " + in_quotes(w) + " is not a " + t.name + " value");
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const { in_.fail(what); }

 private:
  MeshText in_;
  std::size_t last_line_;  // of the latest value: where a truncated file ends
};

// The values of a binary body, in either byte order.
class BinaryValues {
 public:
  BinaryValues(const std::string& path, std::string_view bytes, std::size_t start, bool big)
      : path_(path), bytes_(bytes), pos_(start), big_(big) {}
  std::uint64_t bytes_left() const { return bytes_.size() - pos_; }
  std::uint64_t max_entries(const TypeInfo& t) const { return bytes_left() / t.bytes; }
  double value(const TypeInfo& t, const std::string& item) {
    if (bytes_left() < t.bytes) {
      fail("the file ends in " + item + "; it is truncated or a count is wrong");
    }
    std::uint64_t u = 0;  // the bytes as an unsigned number, most significant first
    for (std::size_t k = 0; k < t.bytes; ++k) {
      const std::size_t at = big_ ? k : t.bytes - 1 - k;
      u = (u << 8) | static_cast<unsigned char>(bytes_[pos_ + at]);
    }
    pos_ += t.bytes;
    switch (t.type) {
      case Type::Int8:
        return static_cast<std::int8_t>(u);
      case Type::UInt8:
        return static_cast<std::uint8_t>(u);
      case Type::Int16:
        return static_cast<std::int16_t>(u);
      case Type::UInt16:
        return static_cast<std::uint16_t>(u);
      case Type::Int32:
        return static_cast<std::int32_t>(u);
      case Type::UInt32:
        return static_cast<std::uint32_t>(u);
      case Type::Float32: {
        const auto bits = static_cast<std::uint32_t>(u);
        float f = 0;
        std::memcpy(&f, &bits, sizeof f);
        return f;
      }
      case Type::Float64: {
        double d = 0;
        std::memcpy(&d, &u, sizeof d);
        return d;
      }
    }
    return 0;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput(path_ + ", byte " + std::to_string(pos_) + ": " + what);
  }

 private:
  std::string path_;
  std::string_view bytes_;
  std::size_t pos_;
  bool big_;
};

inline bool is_vertex_element(const Element& e) {
  return e.name == "vertex" || e.name == "vertices";
}
inline bool is_face_element(const Element& e) { return e.name == "face" || e.name == "faces"; }

/// The list of a face element's corners: "vertex_indices", else "vertex_index" (-1 if none).
inline int corner_list(const Element& e) {
  const int k = e.find("vertex_indices");
  return k >= 0 ? k : e.find("vertex_index");
}

// Reads the body, element after element, into `soup`. `vertices` is the number of
// vertices the header declares (all vertex elements), which face indices must stay under.
template <class Values>
void read_body(Values& in, const std::vector<Element>& elements, std::uint64_t vertices,
               PolygonSoup& soup) {
  for (const Element& e : elements) {
    if (e.count == 0 || e.properties.empty()) continue;  // nothing stored: nothing to read
    const bool vertex = is_vertex_element(e), face = is_face_element(e);
    const int xyz[3] = {e.find("x"), e.find("y"), e.find("z")};
    const int corners = face ? corner_list(e) : -1;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const std::string item = vertex ? "vertex " + std::to_string(soup.points.size())
                               : face ? "face " + std::to_string(soup.polygons.size())
                                      : "element " + in_quotes(e.name) + " " + std::to_string(i);
      std::array<double, 3> p{};
      std::vector<std::size_t> polygon;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& prop = e.properties[k];
        if (!prop.count) {
          const double v = in.value(*prop.type, item);
          for (int c = 0; c < 3; ++c) {
            if (vertex && xyz[c] == static_cast<int>(k)) p[c] = v;
          }
          continue;
        }
        const double n = in.value(*prop.count, item);
        const bool is_corners = static_cast<int>(k) == corners;
        if (n < 0)
          in.fail(item + ": the list " + in_quotes(prop.name) +
                  " has a negative length; the file is damaged");
        if (is_corners && n < 3) {
          in.fail(item + " has " + std::to_string(static_cast<long long>(n)) +
                  " corners; a face needs at least 3");
        }
        // The length comes from the file: check it against the bytes left before reserving.
        if (n > static_cast<double>(in.max_entries(*prop.type))) {
          in.fail(item + ": the list " + in_quotes(prop.name) + " claims " +
                  std::to_string(static_cast<unsigned long long>(n)) + " entries, more than the " +
                  std::to_string(in.bytes_left()) +
                  " bytes left in the file hold; the file is damaged");
        }
        const auto length = static_cast<std::size_t>(n);
        if (is_corners) polygon.reserve(length);
        for (std::size_t j = 0; j < length; ++j) {
          const double index = in.value(*prop.type, item);
          if (!is_corners) continue;
          if (index < 0 || index >= static_cast<double>(vertices)) {
            in.fail(item + " names vertex " + std::to_string(static_cast<long long>(index)) +
                    ", but the file has " + vertex_range(vertices) + "; fix the index");
          }
          polygon.push_back(static_cast<std::size_t>(index));
        }
      }
      if (vertex) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
          in.fail(item + " has a coordinate that is not a finite number; fix the coordinate");
        }
        soup.points.push_back(p);
      } else if (face) {
        soup.polygons.push_back(std::move(polygon));
      }
    }
  }
}

}  // namespace ply

inline PolygonSoup read_ply(const std::string& path, std::string_view bytes) {
  using ply::Element;
  using ply::Property;
  MeshText in(path, bytes);
  const auto first = words_of(in.line_rest());
  if (first.empty() || first[0] != "ply") {
    in.fail("a PLY file starts with the line 'ply', not " +
                in_quotes(first.empty() ? std::string_view() : first[0]) + "; is this a PLY file?",
            1);
  }
  const std::size_t format_line = in.line();
  const auto format = words_of(in.line_rest());
  if (format.size() < 3 || format[0] != "format") {
    in.fail("expected 'format ascii 1.0' (or binary_little_endian, binary_big_endian)",
            format_line);
  }
  if (format[1] != "ascii" && format[1] != "binary_little_endian" &&
      format[1] != "binary_big_endian") {
    in.fail("unknown format " + in_quotes(format[1]) +
                "; PLY is ascii, binary_little_endian or binary_big_endian",
            format_line);
  }

  // The header, whole, before any data.
  std::vector<Element> elements;
  for (;;) {
    if (in.at_end()) {
      in.fail("the header has no end_header line; the file is truncated or not a PLY file");
    }
    const std::size_t line = in.line();
    const auto words = words_of(in.line_rest());
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "end_header") break;
    if (words[0] == "element") {
      long long count = 0;
      if (words.size() < 3 || !parse_integer(words[2], count) || count < 0) {
        const std::string found = words.size() < 3 ? "" : ", not " + in_quotes(words[2]);
        in.fail("an element line reads 'element NAME COUNT', COUNT a whole number" + found, line);
      }
      elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), line, {}});
      continue;
    }
    if (words[0] != "property") {
      in.fail("unknown header line " + in_quotes(words[0]) +
                  "; a PLY header holds format, element, property, comment, obj_info and "
                  "end_header lines",
              line);
    }
    const bool list = words.size() > 1 && words[1] == "list";
    if (list ? words.size() < 5 : words.size() < 3) {
      in.fail(list ? "a list property reads 'property list COUNT_TYPE ENTRY_TYPE NAME', e.g. "
                     "'property list uchar int vertex_indices'"
                   : "a property line reads 'property TYPE NAME', e.g. 'property float x'",
              line);
    }
    const std::string_view name = words[list ? 4 : 2];
    if (elements.empty()) {
      in.fail("the property " + in_quotes(name) +
                  " comes before any element line; a PLY header declares 'element NAME COUNT' "
                  "first, then its properties",
              line);
    }
    Property prop;
    prop.name = std::string(name);
    for (std::size_t k = 1; k < (list ? 3u : 2u); ++k) {
      const std::string_view type = words[k + (list ? 1 : 0)];
      const ply::TypeInfo* info = ply::type_info(type);
      if (!info) {
        in.fail("unknown type " + in_quotes(type) + " of the property " + in_quotes(name) +
                    "; PLY types are char, uchar, short, ushort, int, uint, float, double "
                    "(or int8, uint8, ..., float64)",
                line);
      }
      if (list && k == 1 && !info->integer) {
        in.fail("the length of the list " + in_quotes(name) + " has type " + in_quotes(type) +
                    "; it must be an integer type (e.g. uchar)",
                line);
      }
      (list && k == 1 ? prop.count : prop.type) = info;
    }
    elements.back().properties.push_back(prop);
  }
  const std::size_t body = in.position(), body_line = in.line();

  // What the data must hold: x, y, z for vertices, an integer list of corners for faces.
  const bool binary = format[1] != "ascii";
  std::uint64_t vertices = 0, need = 0;
  for (const Element& e : elements) {
    const std::string named = "the element " + in_quotes(e.name);
    if (ply::is_vertex_element(e) && e.count > 0) {
      for (const char* c : {"x", "y", "z"}) {
        const int k = e.find(c);
        if (k < 0 || e.properties[k].count) {
          in.fail(named + (k < 0 ? " has no property '" : " has a list as property '") + c +
                      "'; vertices need the numbers x, y and z",
                  e.line);
        }
      }
    }
    if (ply::is_vertex_element(e)) vertices = add_product(vertices, e.count, 1);
    const int corners = ply::is_face_element(e) ? ply::corner_list(e) : -1;
    if (ply::is_face_element(e) && e.count > 0) {
      if (corners < 0 || !e.properties[corners].count || !e.properties[corners].type->integer) {
        in.fail(named +
                    " has no list of integers 'vertex_indices' (or 'vertex_index'); faces "
                    "need one, e.g. 'property list uchar int vertex_indices'",
                e.line);
      }
    }
    // The fewest bytes an item can take: an ascii value a digit and a separator, a binary
    // one its size; a list its length, and at least 3 entries for a face's corners.
    std::uint64_t item = 0;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const Property& p = e.properties[k];
      const std::uint64_t entries = static_cast<int>(k) == corners ? 3 : 0;
      if (binary) {
        item += p.count ? p.count->bytes + entries * p.type->bytes : p.type->bytes;
      } else {
        item += 2 + (p.count ? 2 * entries : 0);
      }
    }
    need = add_product(need, e.count, item);
    const std::uint64_t left = bytes.size() - body + (binary ? 0 : 1);
    if (need > left) {
      in.fail(named + " has " + std::to_string(e.count) + " items, which with the elements " +
                  "before it take at least " + std::to_string(need - (binary ? 0 : 1)) +
                  " bytes, but only " + std::to_string(bytes.size() - body) +
                  " bytes follow the header; the counts are wrong or the file is truncated",
              e.line);
    }
  }

  PolygonSoup soup;
  soup.points.reserve(vertices);
  for (const Element& e : elements) {
    if (ply::is_face_element(e)) soup.polygons.reserve(soup.polygons.size() + e.count);
  }
  if (binary) {
    ply::BinaryValues values(path, bytes, body, format[1] == "binary_big_endian");
    ply::read_body(values, elements, vertices, soup);
  } else {
    ply::AsciiValues values(path, bytes, body, body_line);
    ply::read_body(values, elements, vertices, soup);
  }
  return soup;
}

}  // namespace disktune::detail
