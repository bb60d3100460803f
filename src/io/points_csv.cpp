// SPDX-License-Identifier: GPL-3.0-or-later
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune {
namespace {

// Shortest decimal form that reads back to the same double (std::to_chars).
void put_number(std::ostream& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.write(buf, res.ptr - buf);
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace

void write_points_csv(const std::string& path, const Packing& packing) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,r\n";
    for (DiskId id = 0; id < packing.id_bound(); ++id) {
      if (!packing.alive(id)) continue;
      const Vec2 c = packing.center(id);
      put_number(out, c.x);
      out << ',';
      put_number(out, c.y);
      out << ',';
      put_number(out, packing.radius(id));
      out << '\n';
    }
  });
}

std::vector<PointRecord> read_points_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read '" + path + "': no such file or not readable");
  std::vector<PointRecord> out;
  std::string line;
  std::size_t lineno = 0;
  auto fail = [&](const std::string& what) {
    std::ostringstream msg;
    msg << path << ":" << lineno << ": " << what;
    throw InvalidInput(msg.str());
  };
  ++lineno;
  if (!std::getline(in, line)) fail("empty file; expected the header 'x,y,r'");
  if (trim(line) != "x,y,r") fail("expected the header 'x,y,r', found '" + trim(line) + "'");
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty()) continue;
    double v[3];
    const char* p = t.data();
    const char* end = t.data() + t.size();
    for (int k = 0; k < 3; ++k) {
      const auto res = std::from_chars(p, end, v[k]);
      if (res.ec != std::errc() || !std::isfinite(v[k])) {
        fail("expected three finite numbers 'x,y,r', found '" + t + "'");
      }
      p = res.ptr;
      if (k < 2) {
        if (p == end || *p != ',') fail("expected three comma-separated numbers, found '" + t + "'");
        ++p;
      }
    }
    if (p != end) fail("unexpected text after the third number in '" + t + "'");
    if (!(v[2] > 0)) fail("radius must be positive, found '" + t + "'");
    out.push_back({v[0], v[1], v[2]});
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
      } else {
        where << f.extent.x << " x " << f.extent.y << " box; give the box with --width and --height";
      }
      throw InvalidInput(where.str());
    }
    const double r = packing.radius_at(c);
    if (std::abs(p.r - r) > kRelTol * r) {
      where << "radius " << p.r << " differs from the radius " << r << " asked for at its center";
      if (packing.sizing()) {
        where << " by the sizing " << packing.sizing()->description() << "; give the sizing it was made with";
      } else {
        where << "; disktune tunes uniform-radius packings: pass --radius " << p.r;
      }
      throw InvalidInput(where.str());
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
