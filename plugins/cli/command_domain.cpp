// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_domain.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "disktune/boundary.h"
#include "disktune/errors.h"
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
  if (args.has_radius == !args.sizing.empty()) {
    throw InvalidInput("give the disk radius with --radius R, or radii that vary with --sizing SPEC "
                       "(one of the two)");
  }
  if (args.sizing.empty()) {
    d.radius = args.radius;
    d.box ? d.box->validate_radius(d.radius) : d.planar->validate_radius(d.radius);
    d.unit = density_unit(d.empty_packing(), d.area());
  } else {
    d.sizing = std::make_shared<const Sizing>(parse_sizing(args.sizing, d.planar));
    SizingStats stats;  // sampling the sizing refuses L >= 1/2
    d.unit = density_unit(sized_packing(d.box ? d.box->frame() : d.planar->frame(), d.planar, d.sizing, &stats),
                          d.area());
    if (stats.lipschitz > 0.25) {
      std::fprintf(stderr,
                   "disktune: warning: the sizing's gradation L = %.3g is above 0.25: the smallest "
                   "Delaunay angle is only guaranteed to be %.1f degrees (docs/sizing.md)\n",
                   stats.lipschitz, angle_bound_degrees(stats.lipschitz));
    }
  }
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

std::string CommandDomain::radius_text() const {
  std::ostringstream s;
  if (sizing) {
    s << "sizing " << sizing->description();
  } else {
    s << "r = " << radius;
  }
  return s.str();
}

std::string CommandDomain::density_text(std::size_t count) const {
  const double eta = static_cast<double>(count) / unit;
  char text[64];
  std::snprintf(text, sizeof text, "eta = %.4f, rho = %.4f", eta,
                std::sqrt(eta * 2 * std::sqrt(3.0) / 3.14159265358979323846));
  return text;
}

Packing CommandDomain::empty_packing() const {
  const Frame& frame = box ? box->frame() : planar->frame();
  if (sizing) return sized_packing(frame, planar, sizing);
  Packing packing(frame, radius);
  packing.set_domain(planar);
  return packing;
}

Packing CommandDomain::sample(Rng& rng) const {
  if (sizing) return box ? sample_mps(*box, sizing, rng) : sample_mps(planar, sizing, rng);
  return box ? sample_mps(*box, radius, rng) : sample_mps(planar, radius, rng);
}

Packing CommandDomain::read(const std::string& csv, bool check) const {
  Packing packing = empty_packing();
  read_packing_csv(csv, packing);
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
