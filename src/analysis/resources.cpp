// SPDX-License-Identifier: GPL-3.0-or-later
// What a job needs before it starts (resources.h): the count from the density integral
// of its radii, the memory from a model of the grids and arrays sampling and tuning
// build (docs/sizing.md, "What a job needs"), and the memory this process may use.
#include "disktune/resources.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "disktune/errors.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The model's constants, fitted to the peak resident memory (/usr/bin/time -v) of
// `disktune sample` and `tune --target-fraction 0.8` at several radii (docs/sizing.md,
// "What a job needs", has the runs). Sampling in the box and planar domains is the
// neighbour grid and the dart cells (each counted apart below; 182 and 213 bytes a
// disk in all, measured, for one radius) and the packing's arrays:
constexpr double kSampleBytesPerDisk = 40;
// A dart cell of planar sampling: 16 bytes, in an array that may hold twice as many.
constexpr double kBytesPerDartCell = 32;
// A neighbour-grid slot (center, radius, id: 32 bytes); each cell also has a 16-bit count.
constexpr double kBytesPerGridSlot = 32;
// Tuning to 0.8, per disk reached, besides the neighbour grid: 324 bytes measured in the
// box (174 169 -> 254 648 disks), 559 in a planar domain (140 479 -> 203 718).
constexpr double kBoxTuneBytesPerDisk = 330;
constexpr double kPlanarTuneBytesPerDisk = 560;
// On a surface (a hashed grid, darts drawn one at a time: memory follows the disks):
// 311 bytes a disk sampling, 258 tuning (slopes between two radii), 384 in all at 89 259.
constexpr double kSurfaceBytesPerDisk = 400;

void check_radius(double r) {
  if (!(std::isfinite(r) && r > 0)) {
    std::ostringstream msg;
    msg << "radius must be a finite positive number, got " << r;
    throw InvalidInput(msg.str());
  }
}

// Cells of at most `side` along a length, as the grids lay them out (SpatialGrid caps
// them at 32768 a side; the dart cells are not capped).
double cells_along(double length, double side, bool capped) {
  const double n = std::max(1.0, std::ceil(length / side));
  return capped ? std::min(n, 32768.0) : n;
}

// Each neighbour-grid cell has as many slots as the fullest one needs (a power of two)
// and a 16-bit count; random packings fill their densest cells above the mean.
double grid_bytes(const ResourceEstimate& e) {
  double slots = 1;
  while (slots < 1.5 * e.densest_cell) slots *= 2;
  return e.grid_cells * (slots * kBytesPerGridSlot + 2);
}


// The box or a planar domain over `frame`: darts in cells of diagonal r_min, a neighbour
// grid of cells of diagonal r_grid (the packing's largest radius), `densest` disks at area
// fraction 1 in its fullest cell (0: one radius, at most one disk a cell).
ResourceEstimate planar_estimate(const Frame& frame, bool periodic_box, double unit, double r_min,
                                 double r_max, double r_grid, double densest) {
  ResourceEstimate e;
  e.unit = unit;
  e.disks = kMpsAreaFraction * unit;
  e.min_radius = r_min, e.max_radius = r_max;
  const double dart_side = r_min / std::sqrt(2.0);
  e.dart_cells = cells_along(frame.extent.x, dart_side, false) * cells_along(frame.extent.y, dart_side, false);
  const double grid_side = r_grid / std::sqrt(2.0);
  e.grid_cells = cells_along(frame.extent.x, grid_side, true) * cells_along(frame.extent.y, grid_side, true);
  // One radius: a cell of diagonal r holds one disk, unless the grid was capped.
  e.densest_cell = densest > 0 ? kMpsAreaFraction * densest : e.disks / e.grid_cells;
  e.bytes_per_disk = periodic_box ? kBoxTuneBytesPerDisk : kPlanarTuneBytesPerDisk;
  e.sample_bytes = kBytesPerDartCell * e.dart_cells + kSampleBytesPerDisk * e.disks;
  e.bytes = grid_bytes(e) + e.sample_bytes;
  return e;
}

ResourceEstimate one_radius(const Frame& frame, bool periodic_box, double area, double r) {
  check_radius(r);
  const double unit = 4 * area / (kPi * r * r);
  ResourceEstimate e = planar_estimate(frame, periodic_box, unit, r, r, r, 0);
  std::ostringstream s;
  s << "radius " << r;
  e.subject = s.str();
  return e;
}

ResourceEstimate sized(const Frame& frame, const PlanarDomain* domain, const Sizing& sizing) {
  const bool periodic_box = domain == nullptr;
  const SizingStats stats = measure_sizing(sizing, frame, domain);
  const double unit = density_integral(sizing, frame, domain);
  // As sized_packing: between its samples r may exceed their largest by a little.
  const double r_grid = stats.upper;
  const double densest = densest_cell_integral(sizing, frame, domain, r_grid / std::sqrt(2.0));
  ResourceEstimate e = planar_estimate(frame, periodic_box, unit, stats.min, stats.max, r_grid, densest);
  e.subject = "the sizing \"" + sizing.description() + "\"";
  return e;
}

std::string box_text(const PeriodicBox& box) {
  std::ostringstream s;
  s << "the " << box.width() << " x " << box.height() << " box";
  return s.str();
}

std::string area_text(const char* what, double area) {
  std::ostringstream s;
  s.precision(4);
  s << what << " of area " << area;
  return s.str();
}

// "57 GiB", "3.1 GiB", "500 MiB".
std::string bytes_text(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (bytes >= 1024 && u < 6) bytes /= 1024, ++u;
  char text[48];
  if (bytes >= 1024) {  // past EiB: a power of ten of bytes, not "274129142 EiB"
    std::snprintf(text, sizeof text, "%.1e bytes", bytes * std::pow(1024.0, u));
  } else {
    std::snprintf(text, sizeof text, bytes < 10 ? "%.2g %s" : "%.0f %s", bytes, units[u]);
  }
  return text;
}

// Two significant digits: "0.00036", "430", "3.1e8" (not "3.1e+08" or "4.3e+02").
std::string number_text(double v) {
  char text[32];
  if (std::abs(v) >= 100 && std::abs(v) < 1e6) {
    const double unit = std::pow(10.0, std::floor(std::log10(std::abs(v))) - 1);
    std::snprintf(text, sizeof text, "%.0f", std::round(v / unit) * unit);
    return text;
  }
  std::snprintf(text, sizeof text, "%.2g", v);
  std::string s = text;
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::size_t digits = e + 1;
  if (s[digits] == '+') s.erase(digits, 1);
  if (s[digits] == '-') ++digits;
  while (digits + 1 < s.size() && s[digits] == '0') s.erase(digits, 1);
  return s;
}

// The first number after `key` in a "key value" text file (/proc/meminfo, memory.stat),
// or NaN.
double field(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string name;
  double value;
  while (in >> name >> value) {
    if (name == key) return value;
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return std::nan("");
}

// The first number in a file, or NaN ("max" in a cgroup v2 limit file: no limit).
double number_in(const std::string& path) {
  std::ifstream in(path);
  double value;
  return in >> value ? value : std::nan("");
}

// What the cgroup still allows: its limit less what it uses, not counting the file
// cache it can drop (inactive files). v2, then v1; the process's own cgroup, else the
// root of the mount (a container sees its own cgroup there).
double cgroup_room() {
  std::ifstream self("/proc/self/cgroup");
  std::string line, v2_path, v1_path;
  while (std::getline(self, line)) {
    if (line.rfind("0::", 0) == 0) v2_path = line.substr(3);
    const std::size_t at = line.find(":memory:");
    if (at != std::string::npos) v1_path = line.substr(at + 8);
  }
  struct Layout {
    std::string base, path, limit, usage, inactive;
  };
  const Layout layouts[] = {{"/sys/fs/cgroup", v2_path, "memory.max", "memory.current", "inactive_file"},
                            {"/sys/fs/cgroup/memory", v1_path, "memory.limit_in_bytes", "memory.usage_in_bytes",
                             "total_inactive_file"}};
  for (const Layout& l : layouts) {
    for (const std::string& dir : {l.base + l.path, l.base}) {
      const double limit = number_in(dir + "/" + l.limit);
      if (std::isnan(limit)) continue;
      const double usage = number_in(dir + "/" + l.usage);
      double inactive = field(dir + "/memory.stat", l.inactive);
      if (std::isnan(inactive)) inactive = 0;
      return std::isnan(usage) ? limit : limit - std::max(0.0, usage - inactive);
    }
  }
  return kInf;
}

// A soft resource limit less what the process has of it (a /proc/self/status field, kB).
double rlimit_room(int resource, const char* status_field) {
  rlimit rl{};
  if (getrlimit(resource, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY) return kInf;
  double used = field("/proc/self/status", status_field) * 1024;
  if (std::isnan(used)) used = 0;
  return static_cast<double>(rl.rlim_cur) - used;
}

}  // namespace

ResourceEstimate ResourceEstimate::tuned_to(double count) const {
  ResourceEstimate e = *this;
  if (count > disks) {
    e.densest_cell = densest_cell * count / disks;
    e.disks = count;
  }
  e.bytes = grid_bytes(e) + std::max(e.sample_bytes, e.bytes_per_disk * e.disks);
  return e;
}

ResourceEstimate estimate_resources(const PeriodicBox& box, double r) {
  ResourceEstimate e = one_radius(box.frame(), true, box.area(), r);
  e.where = box_text(box);
  return e;
}

ResourceEstimate estimate_resources(const PeriodicBox& box, const Sizing& sizing) {
  ResourceEstimate e = sized(box.frame(), nullptr, sizing);
  e.where = box_text(box);
  return e;
}

ResourceEstimate estimate_resources(const PlanarDomain& domain, double r) {
  ResourceEstimate e = one_radius(domain.frame(), false, domain.area(), r);
  e.where = area_text("this domain", domain.area());
  return e;
}

ResourceEstimate estimate_resources(const PlanarDomain& domain, const Sizing& sizing) {
  ResourceEstimate e = sized(domain.frame(), &domain, sizing);
  e.where = area_text("this domain", domain.area());
  return e;
}

ResourceEstimate estimate_resources(const SurfaceDomain& surface, const SurfaceSizing& sizing) {
  ResourceEstimate e;
  e.unit = density_integral(sizing, surface);
  e.disks = kMpsAreaFraction * e.unit;
  e.min_radius = sizing.min_radius(), e.max_radius = sizing.max_radius();
  e.bytes_per_disk = kSurfaceBytesPerDisk;
  e.sample_bytes = e.bytes = kSurfaceBytesPerDisk * e.disks;
  e.subject = sizing.is_constant() ? "radius " + number_text(sizing.max_radius())
                                   : "the sizing \"" + sizing.description() + "\"";
  e.where = area_text("this surface", surface.area());
  return e;
}

double available_memory() {
  double room = field("/proc/meminfo", "MemAvailable:") * 1024;
  if (std::isnan(room)) room = kInf;
  room = std::min({room, rlimit_room(RLIMIT_AS, "VmSize:"), rlimit_room(RLIMIT_DATA, "VmData:"), cgroup_room()});
  return std::max(0.0, room);
}

void check_resources(const ResourceEstimate& e, double limit) {
  const bool one_radius = e.min_radius == e.max_radius;
  const std::string opening = (one_radius && e.subject.rfind("radius", 0) == 0)
                                  ? e.subject + " is too small for " + e.where
                                  : "the radii of " + e.subject + " are too small for " + e.where;
  if (!(e.bytes <= limit)) {
    // Every part of the model grows as 1 / r^2: radii f times larger need f^2 less.
    // Unless the dart cells, sized by the smallest radius alone, take most of it: then
    // raising that one is the fix.
    const double f = std::sqrt(e.bytes / limit) * 1.01;
    const double darts = kBytesPerDartCell * e.dart_cells, rest = e.bytes - darts;
    std::string fix;
    const bool darts_first = !one_radius && rest < 0.5 * limit;
    if (!darts_first && !(e.disks / (f * f) >= 10)) {
      // Radii that would fit are so large that fewer than 10 disks remain (or none at
      // all: a limit of 0): no radius is the fix.
      throw InvalidInput("the memory allowed, " + bytes_text(limit) + ", is too little for a packing of " + e.where +
                             " (" + e.subject + " needs ~" + bytes_text(e.bytes) +
                             ", and radii large enough to fit would leave fewer than 10 disks); allow more memory",
                         InvalidInput::Remedy::memory);
    }
    if (one_radius) {
      fix = "use r >= " + number_text(e.min_radius * f);
    } else if (darts_first) {
      fix = "darts are thrown on cells as small as the smallest radius, " + number_text(e.min_radius) +
            ", over the whole domain (" + number_text(e.dart_cells) + " cells, ~" + bytes_text(darts) +
            "): raise it to at least " + number_text(e.min_radius * std::sqrt(darts / (limit - rest)) * 1.01);
    } else {
      fix = "make the radii about " + number_text(f) + " times larger (the smallest, " +
            number_text(e.min_radius) + ", at least " + number_text(e.min_radius * f) + ")";
    }
    throw InvalidInput(opening + ": the job needs about " + number_text(e.disks) + " disks (~" + bytes_text(e.bytes) +
                           ") but " + bytes_text(limit) + " are available; " + fix +
                           ", a smaller domain, or allow more memory",
                       InvalidInput::Remedy::memory);
  }
  if (e.densest_cell > kMaxCellDisks) {
    throw InvalidInput("the radii of " + e.subject + " range from " + number_text(e.min_radius) + " to " +
                           number_text(e.max_radius) + " over " + e.where + ": the neighbour grid, whose cells " +
                           "are as wide as the largest radius, would hold about " + number_text(e.densest_cell) +
                           " disks in one cell, more than the " + number_text(kMaxCellDisks) +
                           " it takes; make the smallest radius larger or the largest smaller",
                       InvalidInput::Remedy::sizing);
  }
}

}  // namespace disktune
