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

namespace {

// Reads the CSV into `packing` (frame and radius set), checking each line's radius and,
// through `outside`, its center: `outside` returns what is wrong, or "" when nothing is.
template <class Outside>
void read_disks(const std::string& path, double r, Packing& packing, Outside&& outside) {
  const std::vector<PointRecord> records = read_points_csv(path);
  if (records.empty()) throw InvalidInput("'" + path + "' holds no disks, only a header");
  for (std::size_t k = 0; k < records.size(); ++k) {
    const PointRecord& p = records[k];
    std::ostringstream where;
    where << path << ":" << k + 2 << ": ";  // line 1 is the header
    if (const std::string why = outside(Vec2{p.x, p.y}); !why.empty()) {
      where << "center (" << p.x << ", " << p.y << ") " << why;
      throw InvalidInput(where.str());
    }
    if (std::abs(p.r - r) > kRelTol * r) {
      where << "radius " << p.r << " differs from the radius " << r
            << " asked for; disktune tunes uniform-radius packings: pass --radius " << p.r;
      throw InvalidInput(where.str());
    }
    packing.insert({p.x, p.y}, r);
  }
}

}  // namespace

Packing read_packing_csv(const std::string& path, const PeriodicBox& box, double r) {
  box.validate_radius(r);
  Packing packing(box.frame(), r);
  read_disks(path, r, packing, [&](Vec2 c) {
    if (c.x >= 0 && c.x < box.width() && c.y >= 0 && c.y < box.height()) return std::string();
    std::ostringstream why;
    why << "lies outside the " << box.width() << " x " << box.height()
        << " box; give the box with --width and --height";
    return why.str();
  });
  return packing;
}

Packing read_packing_csv(const std::string& path, std::shared_ptr<const PlanarDomain> domain, double r) {
  domain->validate_radius(r);
  Packing packing(domain->frame(), r);
  packing.set_domain(domain);
  read_disks(path, r, packing, [&](Vec2 c) {
    return domain->contains(c) ? std::string()
                               : std::string("lies outside the domain; give the domain the packing was made for");
  });
  return packing;
}

}  // namespace disktune
