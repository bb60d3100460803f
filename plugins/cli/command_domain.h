// SPDX-License-Identifier: GPL-3.0-or-later
// The domain a command works on, from --domain: the periodic box, or a planar domain
// read from a .poly, .off or .obj file. One place decides how each kind is sampled,
// read back, checked and tuned, so every command treats them alike.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/tuning.h"

namespace disktune::cli {

struct CommandDomain {
  std::optional<PeriodicBox> box;              // --domain periodic
  std::shared_ptr<const PlanarDomain> planar;  // --domain FILE
  std::string file;                            // the file's name, for messages

  double area() const { return box ? box->area() : planar->area(); }
  /// "1 x 1 periodic box" or "planar domain FILE".
  std::string describe() const;
  void validate_radius(double r) const;
  Packing sample(double r, Rng& rng) const;
  /// Reads a packing written for this domain; in a planar domain its boundary disks
  /// become fixed. With `check`, throws InvalidInput unless it is conflict-free and
  /// maximal (what tuning starts from; a report measures whatever it gets).
  Packing read(const std::string& csv, double r, bool check) const;
  TuneResult tune(Packing& packing, const Target& target, Rng& rng, const TuneOptions& options) const;
};

/// Opens the domain named by the options (reads and validates a domain file).
CommandDomain open_domain(const DomainArgs& args);

}  // namespace disktune::cli
