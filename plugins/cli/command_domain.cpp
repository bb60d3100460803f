// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_domain.h"

#include <sstream>

#include "disktune/boundary.h"
#include "disktune/io.h"
#include "disktune/sampling.h"
#include "disktune/voids.h"

namespace disktune::cli {

CommandDomain open_domain(const DomainArgs& args) {
  CommandDomain d;
  if (args.kind == "periodic") {
    d.box.emplace(args.width, args.height);
  } else {
    d.planar = std::make_shared<const PlanarDomain>(read_planar_domain(args.kind));
  }
  d.file = args.kind;
  return d;
}

std::string CommandDomain::describe() const {
  std::ostringstream s;
  if (box) {
    s << box->width() << " x " << box->height() << " periodic box";
  } else {
    s << "planar domain " << file << " (" << planar->loops().size() << " boundary loops, area "
      << planar->area() << ")";
  }
  return s.str();
}

void CommandDomain::validate_radius(double r) const {
  box ? box->validate_radius(r) : planar->validate_radius(r);
}

Packing CommandDomain::sample(double r, Rng& rng) const {
  return box ? sample_mps(*box, r, rng) : sample_mps(planar, r, rng);
}

Packing CommandDomain::read(const std::string& csv, double r, bool check) const {
  Packing packing = box ? read_packing_csv(csv, *box, r) : read_packing_csv(csv, planar, r);
  if (planar) boundary_loops(packing, *planar);
  if (check) validate_packing(packing, csv);
  return packing;
}

TuneResult CommandDomain::tune(Packing& packing, const Target& target, Rng& rng,
                               const TuneOptions& options) const {
  return box ? disktune::tune(packing, *box, target, rng, options)
             : disktune::tune(packing, *planar, target, rng, options);
}

}  // namespace disktune::cli
