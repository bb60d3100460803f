// SPDX-License-Identifier: GPL-3.0-or-later
// Files in and out. Every writer goes through a temporary file renamed into place, so
// a failed write never leaves a half-written output behind.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"

namespace disktune {

/// Writes `path` by calling `write` on a temporary sibling file, then renaming it into
/// place. Throws IoError (naming the path and the reason) and removes the temporary on
/// any failure, including an exception thrown by `write`; a path that is a folder is
/// refused before anything is written. A path that is a device or a
/// pipe (/dev/null, a FIFO) is written straight into instead, never replaced; a symbolic
/// link is written through (its target is replaced, the link stays); an existing file
/// keeps its permissions. While an OutputTransaction is open on this thread, the
/// temporary is kept until the transaction commits.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

/// Several output files as one transaction: while it is open, every write_file_atomically
/// of this thread leaves its finished temporary beside its target; commit() renames them
/// all into place, after all were written. Destroyed without commit (an exception, a
/// refused run), it removes the temporaries and every existing file stays as it was.
/// Transactions do not nest.
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  /// Renames every written file into place, in the order written. Throws IoError when a
  /// rename fails (the files renamed before it stay, the others are removed).
  void commit();
  /// Whether a transaction is open on this thread (a writer of several files opens one
  /// of its own only where none is).
  static bool open_here();

 private:
  struct Staged {
    std::string temporary, target;
    int slot;  // where remove_temporary_outputs finds it
  };
  std::vector<Staged> staged_;
  friend void write_file_atomically(const std::string&, const std::function<void(std::ostream&)>&);
};

/// Removes every temporary output file not yet renamed into place, of every thread.
/// Async-signal-safe (only unlink), for a SIGINT or SIGTERM handler of the program.
void remove_temporary_outputs() noexcept;

/// CSV with header `x,y,r`, one live disk a line in id order, each number in the
/// shortest form that reads back to the same double.
void write_points_csv(const std::string& path, const Packing& packing);

/// CSV with header `x,y,d`: fiber i's center and diameter a line (a fiber RVE, rve.h),
/// numbers as write_points_csv writes them. Throws InvalidInput unless both lists have
/// the same length.
void write_fibers_csv(const std::string& path, const std::vector<Vec2>& centers, const std::vector<double>& diameters);

/// Fiber diameters from a CSV file with the header `d` (one diameter a line: measured
/// ones, say) or `x,y,d` (its d column: the diameters of an arrangement written above).
/// Throws IoError when it cannot be read, InvalidInput "PATH:LINE: ..." for a diameter
/// that is not finite and positive, other content, or no diameter at all.
std::vector<double> read_diameters_csv(const std::string& path);

/// The smallest and largest radius in a points CSV, planar or on a surface (header
/// `x,y,r` or `x,y,z,r`, as the writers here write them). Throws IoError when the file
/// cannot be read and InvalidInput, naming the line, when its content is wrong or it
/// holds no disk.
std::array<double, 2> read_radius_range(const std::string& path);

struct PointRecord {
  double x, y, r;
};
/// Reads a CSV written by write_points_csv (header `x,y,r`). Throws IoError when the
/// file cannot be read and InvalidInput, naming the line, when its content is wrong.
std::vector<PointRecord> read_points_csv(const std::string& path);

/// Reads a CSV of disks (header `x,y,r`) into a packing of `box` with uniform radius r.
/// Throws InvalidInput, naming the line, when a center lies outside the box or a radius
/// differs from r; IoError when the file cannot be read. It does not check conflicts
/// or maximality (see validate_packing in voids.h).
Packing read_packing_csv(const std::string& path, const PeriodicBox& box, double r);

/// Reads a CSV of disks into `packing`, prepared with its frame and, if any, domain and
/// sizing: each center must lie in the box or domain and each radius be the packing's
/// radius_at(center). Throws InvalidInput naming the line, IoError when the file cannot
/// be read. No conflict or maximality check (see validate_packing in voids.h).
void read_packing_csv(const std::string& path, Packing& packing);

/// The same for a planar domain: the packing is restricted to it (Packing::set_domain);
/// a center outside the domain is refused. Boundary disks are not yet marked: see
/// boundary_loops in boundary.h.
Packing read_packing_csv(const std::string& path, std::shared_ptr<const PlanarDomain> domain, double r);

struct SvgStyle {
  double pixels = 800;  ///< width of the picture in pixels
};
/// The packing as an SVG picture: each disk drawn at half its radius (so the disks do
/// not overlap), periodic images where they cross the frame, fixed and frozen disks in
/// their own colors.
void write_packing_svg(const std::string& path, const Packing& packing, const SvgStyle& style = {});

}  // namespace disktune
