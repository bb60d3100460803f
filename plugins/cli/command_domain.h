// SPDX-License-Identifier: GPL-3.0-or-later
// The domain a command works on, from --domain, --width, --height, --radius and
// --sizing: the periodic box, a planar domain read from a .poly, .off or .obj file, or a
// curved surface read from a .off, .obj, .ply or .stl file, with one radius or a sizing
// function. One place decides how each is sampled, read
// back, checked and tuned, so every command treats them alike.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/resources.h"
#include "disktune/sizing.h"
#include "disktune/surface_packing.h"
#include "disktune/tuning.h"

namespace disktune::cli {

struct CommandDomain {
  std::optional<PeriodicBox> box;              // --domain periodic
  std::shared_ptr<const PlanarDomain> planar;  // --domain FILE (flat)
  std::shared_ptr<const SurfaceDomain> surface;          // --domain FILE (curved)
  std::shared_ptr<const SurfaceSizing> surface_sizing;  // its --radius or --sizing
  std::string file;                            // the file's name, for messages
  double radius = 0;                           // --radius (0 with a sizing)
  std::shared_ptr<const Sizing> sizing;        // --sizing
  double unit = 0;                             // the count at area fraction 1 (density_unit)
  ResourceEstimate need;                       // what a maximal sample of it needs

  double area() const { return box ? box->area() : planar ? planar->area() : surface->area(); }
  /// "1 x 1 periodic box", "planar domain FILE (...)" or "surface FILE (...)".
  std::string describe() const;
  /// "r = 0.01" or "sizing 0.005 + 0.01*x".
  std::string radius_text() const;
  /// "eta = 0.5474, rho = 0.7769" for a count (eta relative to the sizing: docs/sizing.md).
  std::string density_text(std::size_t count) const;
  // The box and planar domains (not a surface: see the surface_ members below).
  /// An empty packing for this domain and radius (a sizing is sampled and checked).
  Packing empty_packing() const;
  Packing sample(Rng& rng) const;
  /// Reads a packing written for this domain; in a planar domain its boundary disks
  /// become fixed. With `check`, throws InvalidInput unless it is conflict-free and
  /// maximal (what tuning starts from; a report measures whatever it gets).
  Packing read(const std::string& csv, bool check) const;
  TuneResult tune(Packing& packing, const Target& target, Rng& rng, const TuneOptions& options) const;

  // A surface.
  SurfacePacking empty_surface_packing() const;
  SurfacePacking sample_surface(Rng& rng) const;
  /// Reads samples (x,y,z[,r]) of this surface; disks on its open boundary become fixed.
  /// With `check`, throws InvalidInput unless they are conflict-free and maximal.
  SurfacePacking read_surface(const std::string& csv, bool check) const;
};

/// Whether --domain names a curved surface: a .ply or .stl file always, a .off or .obj
/// file unless all its vertices have the same z (then it is a planar domain). The one
/// place that decides; reads the file for .off and .obj.
bool names_surface(const DomainArgs& args);

/// The surface --domain names (args.kind), with the sharp features --features asks for
/// (an angle in degrees, or "none"). Throws InvalidInput for a bad --features.
std::shared_ptr<const SurfaceDomain> surface_with_features(const DomainArgs& args);

/// `args`, with the radius of the disks in the points file `points` when neither
/// --radius nor --sizing is given and they all have one radius (the file holds it).
/// Throws InvalidInput when their radii differ: the sizing must be given.
DomainArgs with_radius_of(const DomainArgs& args, const std::string& points);

/// Opens the domain named by the options (reads and validates a domain file, parses
/// and checks the sizing, estimates what a sample needs). Throws InvalidInput unless
/// exactly one of --radius and --sizing is given, and, for a command that samples or
/// tunes (args.guarded), when a maximal sample would not fit (check_memory), before
/// anything is allocated for it.
CommandDomain open_domain(const DomainArgs& args);

/// Throws InvalidInput, with the flags that change it, when `estimate` needs more than
/// `max_memory` bytes (0: the memory available, available_memory) or more than the
/// neighbour grid takes (check_resources).
void check_memory(const ResourceEstimate& estimate, double max_memory);
/// The same for the domain's sample tuned to `disks`.
void check_memory(const CommandDomain& domain, const DomainArgs& args, double disks);

}  // namespace disktune::cli
