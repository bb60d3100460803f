// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "disktune/errors.h"
#include "disktune/io.h"
#include "csv_numbers.h"
#include "number_text.h"
#include "radius_mismatch.h"

namespace disktune {
namespace {

// CSV lines come from getline, without '\n': trimmed strips spaces, tabs and '\r'.
using detail::trimmed;

const char* count_word(std::size_t n) {
  static const char* const words[] = {"no", "one", "two", "three", "four", "five"};
  return n < 6 ? words[n] : "that many";
}

}  // namespace

namespace detail {

CsvNumbers read_csv_numbers(const std::string& path, const std::vector<std::string>& headers) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read '" + path + "': no such file or not readable");
  CsvNumbers out;
  std::string line;
  std::size_t lineno = 0;
  auto fail = [&](const std::string& what) {
    std::ostringstream msg;
    msg << path << ":" << lineno << ": " << what;
    throw InvalidInput(msg.str());
  };
  std::string wanted;
  for (std::size_t k = 0; k < headers.size(); ++k) {
    wanted += (k == 0 ? "'" : k + 1 == headers.size() ? " or '" : ", '") + headers[k] + "'";
  }
  ++lineno;
  if (!std::getline(in, line)) fail("empty file; expected the header " + wanted);
  for (const std::string& h : headers) {
    if (trimmed(line) == h) out.header = h;
  }
  if (out.header.empty()) fail("expected the header " + wanted + ", found '" + trimmed(line) + "'");
  out.columns = static_cast<std::size_t>(std::count(out.header.begin(), out.header.end(), ',')) + 1;
  const std::string count = count_word(out.columns);
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trimmed(line);
    if (t.empty()) continue;
    const char* p = t.data();
    const char* end = t.data() + t.size();
    for (std::size_t k = 0; k < out.columns; ++k) {
      double v = 0;
      const auto res = std::from_chars(p, end, v);
      if (res.ec != std::errc() || !std::isfinite(v)) {
        fail("expected " + (out.columns == 1 ? std::string("a finite number") : count + " finite numbers") + " '" +
             out.header + "', found '" + t + "'");
      }
      out.values.push_back(v);
      p = res.ptr;
      if (k + 1 < out.columns) {
        if (p == end || *p != ',') fail("expected " + count + " comma-separated numbers, found '" + t + "'");
        ++p;
      }
    }
    if (p != end) fail("unexpected text after the last number in '" + t + "'");
    out.lines.push_back(lineno);
  }
  return out;
}

void put_csv_row(std::ostream& out, std::initializer_list<double> values) {
  put_numbers(out, values, ",");
  out << '\n';
}

}  // namespace detail

void write_points_csv(const std::string& path, const Packing& packing) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,r\n";
    for (DiskId id = 0; id < packing.id_bound(); ++id) {
      if (!packing.alive(id)) continue;
      const Vec2 c = packing.center(id);
      detail::put_csv_row(out, {c.x, c.y, packing.radius(id)});
    }
  });
}

void write_fibers_csv(const std::string& path, const std::vector<Vec2>& centers, const std::vector<double>& diameters) {
  if (centers.size() != diameters.size()) {
    throw InvalidInput("write_fibers_csv: " + std::to_string(centers.size()) + " centers but " +
                       std::to_string(diameters.size()) + " diameters");
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,d\n";
    for (std::size_t i = 0; i < centers.size(); ++i) detail::put_csv_row(out, {centers[i].x, centers[i].y, diameters[i]});
  });
}

namespace {

// The last column of a CSV with at least one row, each value positive; `what` names it
// in the messages ("radius", "a diameter").
std::vector<double> positive_last_column(const std::string& path, const std::vector<std::string>& headers,
                                         const std::string& what, const std::string& plural) {
  const detail::CsvNumbers rows = detail::read_csv_numbers(path, headers);
  if (rows.rows() == 0) throw InvalidInput("'" + path + "' holds no " + plural + ", only a header");
  std::vector<double> out;
  out.reserve(rows.rows());
  for (std::size_t k = 0; k < rows.rows(); ++k) {
    const double v = rows.at(k, rows.columns - 1);
    if (!(v > 0)) {
      std::ostringstream msg;
      msg << path << ":" << rows.lines[k] << ": " << what << " must be positive, found " << v;
      throw InvalidInput(msg.str());
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace

std::array<double, 2> read_radius_range(const std::string& path) {
  const std::vector<double> radii = positive_last_column(path, {"x,y,r", "x,y,z,r"}, "radius", "disks");
  const auto [least, most] = std::minmax_element(radii.begin(), radii.end());
  return {*least, *most};
}

std::vector<double> read_diameters_csv(const std::string& path) {
  return positive_last_column(path, {"d", "x,y,d"}, "a diameter", "diameters");
}

std::vector<PointRecord> read_points_csv(const std::string& path) {
  const detail::CsvNumbers rows = detail::read_csv_numbers(path, {"x,y,r"});
  std::vector<PointRecord> out;
  out.reserve(rows.rows());
  for (std::size_t k = 0; k < rows.rows(); ++k) {
    const PointRecord p{rows.at(k, 0), rows.at(k, 1), rows.at(k, 2)};
    if (!(p.r > 0)) {
      std::ostringstream msg;
      msg << path << ":" << rows.lines[k] << ": radius must be positive, found " << p.r;
      throw InvalidInput(msg.str());
    }
    out.push_back(p);
  }
  return out;
}

void read_packing_csv(const std::string& path, Packing& packing) {
  const std::vector<PointRecord> records = read_points_csv(path);
  if (records.empty()) throw InvalidInput("'" + path + "' holds no disks, only a header");
  const Frame& f = packing.frame();
  for (std::size_t k = 0; k < records.size(); ++k) {
    const PointRecord& p = records[k];
    const Vec2 c{p.x, p.y};
    std::ostringstream where;
    where << path << ":" << k + 2 << ": ";  // line 1 is the header
    if (packing.domain() ? !packing.domain()->contains(c)
                         : !(c.x >= f.origin.x && c.x < f.origin.x + f.extent.x &&
                             c.y >= f.origin.y && c.y < f.origin.y + f.extent.y)) {
      where << "center (" << p.x << ", " << p.y << ") lies outside the ";
      if (packing.domain()) {
        where << "domain; give the domain the packing was made for";
        throw InvalidInput(where.str(), InvalidInput::Remedy::domain);
      }
      where << f.extent.x << " x " << f.extent.y << " box; give the width and height of the box the packing "
            << "was made for";
      throw InvalidInput(where.str(), InvalidInput::Remedy::box_size);
    }
    const double r = packing.radius_at(c);
    if (std::abs(p.r - r) > kRelTol * r) {
      where << "radius " << p.r << " differs from the radius " << r << " asked for at its center";
      if (packing.sizing()) where << " by the sizing " << packing.sizing()->description();
      const auto [lo, hi] = std::minmax_element(records.begin(), records.end(),
                                                [](const PointRecord& a, const PointRecord& b) { return a.r < b.r; });
      detail::throw_radius_mismatch(where, lo->r, hi->r, "packing was");
    }
    packing.insert(c, r);
  }
}

Packing read_packing_csv(const std::string& path, const PeriodicBox& box, double r) {
  box.validate_radius(r);
  Packing packing(box.frame(), r);
  read_packing_csv(path, packing);
  return packing;
}

Packing read_packing_csv(const std::string& path, std::shared_ptr<const PlanarDomain> domain, double r) {
  domain->validate_radius(r);
  Packing packing(domain->frame(), r);
  packing.set_domain(std::move(domain));
  read_packing_csv(path, packing);
  return packing;
}

}  // namespace disktune
