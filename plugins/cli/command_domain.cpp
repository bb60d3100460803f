// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_domain.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "disktune/boundary.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/sampling.h"
#include "disktune/surface_features.h"
#include "disktune/surface_io.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"
#include "disktune/voids.h"

namespace disktune::cli {

namespace {

// The library says what is wrong and what to do in its own terms; the command adds its
// flags. An InvalidInput from `call` comes back with the option the call read
// (`option`, e.g. "--sizing", or empty) in place of the library's name for it when the
// message opens with that name ("sizing \"0.0x\": ..." becomes "--sizing \"0.0x\": ..."),
// else in front of the message, and with the flag for what the message asks to change
// (InvalidInput::remedy) at the end: "...; give the radius the packing was made with,
// 0.03 (--radius 0.03)".
std::string in_flags(const InvalidInput& e, const std::string& option) {
  std::string text = e.what();
  if (!option.empty()) {
    const std::string name = option.substr(2) + " ";
    text = text.compare(0, name.size(), name) == 0 ? option + text.substr(name.size() - 1) : option + ": " + text;
  }
  switch (e.remedy()) {
    case InvalidInput::Remedy::none: break;
    case InvalidInput::Remedy::radius: text += " (--radius" + (e.value().empty() ? "" : " " + e.value()) + ")"; break;
    case InvalidInput::Remedy::sizing: text += " (--sizing)"; break;
    case InvalidInput::Remedy::domain: text += " (--domain)"; break;
    case InvalidInput::Remedy::box_size: text += " (--width, --height)"; break;
    case InvalidInput::Remedy::sample: text += " ('disktune sample')"; break;
    case InvalidInput::Remedy::memory: text += " (--max-memory SIZE)"; break;
  }
  return text;
}

template <class Call>
auto with_flags(const std::string& option, Call&& call) -> decltype(call()) {
  try {
    return call();
  } catch (const InvalidInput& e) {
    throw InvalidInput(in_flags(e, option));
  }
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

CommandDomain open_surface(const DomainArgs& args) {
  CommandDomain d;
  d.file = args.kind;
  d.surface = surface_with_features(args);
  if (args.has_radius == !args.sizing.empty()) {
    throw InvalidInput("give the disk radius with --radius R, or radii that vary over the surface with "
                       "--sizing curvature[:RMIN,RMAX], an expression in x, y, z or a number (one of "
                       "the two)");
  }
  if (args.sizing.empty()) {
    if (!(args.radius > 0) || !std::isfinite(args.radius)) {
      throw InvalidInput("--radius: the radius must be a finite positive number");
    }
    d.radius = args.radius;
    d.surface_sizing = std::make_shared<const SurfaceSizing>(SurfaceSizing::constant(args.radius));
    // As on a planar domain: a radius that would leave a feature or boundary without
    // disks of its own, next to another, becomes the largest radius of auto:.
    if (!curves_fit(*d.surface, args.radius)) {
      d.surface_sizing = std::make_shared<const SurfaceSizing>(thickness_sizing(*d.surface, args.radius));
      say(
                   "disktune: note: r = %g does not fit this surface (two of its feature curves or boundaries "
                   "are closer than r along more than 3r); using --sizing auto:%g, which shrinks r near them "
                   "(docs/surfaces.md)\n",
                   args.radius, args.radius);
    }
  } else {
    d.surface_sizing = std::make_shared<const SurfaceSizing>(
        with_flags("--sizing", [&] { return parse_surface_sizing(args.sizing, *d.surface); }));
  }
  d.need = estimate_resources(*d.surface, *d.surface_sizing);
  if (args.guarded) check_memory(d.need, args.max_memory);
  d.unit = d.need.unit;
  return d;
}

}  // namespace

// The surface with the features --features asks for: ANGLE[:STRAY] or none.
std::shared_ptr<const SurfaceDomain> surface_with_features(const DomainArgs& args) {
  SurfaceDomain surface = disktune::read_surface(args.kind);
  if (args.features == "none") return std::make_shared<const SurfaceDomain>(std::move(surface));
  FeatureOptions options;
  const std::size_t colon = args.features.find(':');
  const std::string angle = args.features.substr(0, colon);
  const std::string stray = colon == std::string::npos ? "" : args.features.substr(colon + 1);
  char* end = nullptr;
  options.angle = std::strtod(angle.c_str(), &end);
  bool ok = !angle.empty() && *end == '\0' && options.angle > 0 && options.angle < 180;
  if (ok && colon != std::string::npos) {
    options.stray_length = std::strtod(stray.c_str(), &end);
    ok = !stray.empty() && *end == '\0' && options.stray_length >= 0 && options.stray_length <= 1e6;
  }
  if (!ok) {
    throw InvalidInput(
        "--features " + args.features +
        ": give a dihedral angle in degrees strictly between 0 and 180 (60 is the default), "
        "optionally with ':STRAY', the share of the bounding-box diagonal under which a group "
        "of feature edges with a loose end is dropped (0.2 is the default, 0 keeps all), "
        "or 'none'");
  }
  surface.set_features(detect_features(surface, options));
  return std::make_shared<const SurfaceDomain>(std::move(surface));
}

bool names_surface(const DomainArgs& args) {
  if (args.kind == "periodic") return false;
  const std::string ext = lower_extension(args.kind);
  if (ext == ".ply" || ext == ".stl") return true;
  if (ext == ".off" || ext == ".obj") return !is_flat_mesh_file(args.kind);
  return false;
}

DomainArgs with_radius_of(const DomainArgs& args, const std::string& points) {
  if (args.has_radius || !args.sizing.empty() || points.empty()) return args;
  const auto [least, most] = read_radius_range(points);
  if (least != most) {
    char range[64];
    std::snprintf(range, sizeof range, "%g to %g", least, most);
    throw InvalidInput("the disks in '" + points + "' have radii from " + range +
                       ": give the sizing they were made with (--sizing SPEC)");
  }
  DomainArgs out = args;
  out.radius = least;
  out.has_radius = true;
  return out;
}

CommandDomain open_domain(const DomainArgs& args) {
  const std::string ext = lower_extension(args.kind);
  if (args.kind != "periodic" && ext != ".poly" && ext != ".off" && ext != ".obj" && ext != ".ply" &&
      ext != ".stl") {
    throw InvalidInput("--domain " + args.kind + ": unknown kind of domain" +
                       (ext.empty() ? std::string() : " (extension '" + ext + "')") +
                       "; give 'periodic', a planar domain file (.poly, or a flat .off or .obj "
                       "mesh) or a surface file (.off, .obj, .ply, .stl)");
  }
  if (args.has_box_size && args.kind != "periodic") {
    throw InvalidInput("--width and --height size the periodic box; --domain " + args.kind +
                       " has its own size (leave them out, or scale the file)");
  }
  if (names_surface(args)) return open_surface(args);
  if (args.has_features) {
    throw InvalidInput("--features applies to curved surfaces only; --domain " + args.kind +
                       " is not one (leave --features out)");
  }
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
  // A radius too large for two corners of a planar domain (each holds a disk) becomes
  // the largest radius of a feature sizing, which shrinks it near small features. What a
  // sample needs is known, and refused when too much, before anything is built for it
  // (a packing's grid alone grows as 1 / r^2).
  const bool fits = args.sizing.empty() && (d.box || !std::isfinite(args.radius) || !(args.radius > 0) ||
                                            d.planar->corners_fit(args.radius));
  if (fits) {
    d.radius = args.radius;
    d.need = d.box ? estimate_resources(*d.box, d.radius) : estimate_resources(*d.planar, d.radius);
    if (args.guarded) check_memory(d.need, args.max_memory);
    d.box ? d.box->validate_radius(d.radius) : d.planar->validate_radius(d.radius);
  } else {
    if (args.sizing.empty()) {
      d.sizing = std::make_shared<const Sizing>(feature_sizing(d.planar, args.radius));
      say(
                   "disktune: note: r = %g does not fit this domain (two of its corners are closer than r); "
                   "using --sizing auto:%g, which shrinks r near small features (docs/sizing.md)\n",
                   args.radius, args.radius);
    } else {
      d.sizing = std::make_shared<const Sizing>(with_flags("--sizing", [&] { return parse_sizing(args.sizing, d.planar); }));
    }
    const Frame& frame = d.box ? d.box->frame() : d.planar->frame();
    const SizingStats stats = measure_sizing(*d.sizing, frame, d.planar.get());
    check_gradation(stats);  // L >= 1/2: no angle bound
    d.need = d.box ? estimate_resources(*d.box, *d.sizing) : estimate_resources(*d.planar, *d.sizing);
    if (args.guarded) check_memory(d.need, args.max_memory);
    if (stats.lipschitz > 0.25) {
      std::fprintf(stderr,
                   "disktune: warning: the sizing's gradation L = %.3g is above 0.25: the smallest "
                   "Delaunay angle is only guaranteed to be %.1f degrees (docs/sizing.md)\n",
                   stats.lipschitz, angle_bound_degrees(stats.lipschitz));
    }
  }
  d.unit = d.need.unit;  // density_unit's figure, without building a packing
  return d;
}

void check_memory(const ResourceEstimate& estimate, double max_memory) {
  with_flags("", [&] { check_resources(estimate, max_memory > 0 ? max_memory : available_memory()); });
}

void check_memory(const CommandDomain& domain, const DomainArgs& args, double disks) {
  check_memory(domain.need.tuned_to(disks), args.max_memory);
}

std::string CommandDomain::describe() const {
  std::ostringstream s;
  if (box) {
    s << box->width() << " x " << box->height() << " periodic box";
  } else if (surface) {
    s << "surface " << file << " (" << surface->vertices().size() << " vertices, "
      << surface->triangles().size() << " triangles, genus " << surface->genus() << ", ";
    if (surface->is_closed()) {
      s << "closed";
    } else {
      s << surface->boundary_loops().size() << " boundary loop"
        << (surface->boundary_loops().size() == 1 ? "" : "s");
      std::size_t on_loops = 0;  // corners on the boundary: its sharp turns, features meeting it
      for (const auto& loop : surface->boundary_loops())
        for (const std::size_t v : loop)
          on_loops += std::binary_search(surface->corners().begin(), surface->corners().end(), v);
      if (on_loops > 0) s << " with " << on_loops << " corner" << (on_loops == 1 ? "" : "s");
    }
    const auto& f = surface->features();
    if (!f.curves.empty()) {
      s << ", " << f.curves.size() << " feature curve" << (f.curves.size() == 1 ? "" : "s") << " and "
        << f.corners.size() << " corner" << (f.corners.size() == 1 ? "" : "s");
    }
    s << ", area " << surface->area() << ")";
  } else {
    s << "planar domain " << file << " (" << planar->loops().size() << " boundary loops, area "
      << planar->area() << ")";
  }
  return s.str();
}

std::string CommandDomain::radius_text() const {
  std::ostringstream s;
  if (surface_sizing && !surface_sizing->is_constant()) {
    s << "sizing " << surface_sizing->description();
  } else if (surface_sizing) {
    s << "r = " << surface_sizing->max_radius();
  } else if (sizing) {
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
                relative_radius_for(eta));
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
  with_flags("", [&] {
    read_packing_csv(csv, packing);
    if (planar) boundary_loops(packing, *planar);
    if (check) validate_packing(packing, csv);
  });
  return packing;
}

TuneResult CommandDomain::tune(Packing& packing, const Target& target, Rng& rng,
                               const TuneOptions& options) const {
  return box ? disktune::tune(packing, *box, target, rng, options)
             : disktune::tune(packing, *planar, target, rng, options);
}

SurfacePacking CommandDomain::empty_surface_packing() const {
  return SurfacePacking(surface, *surface_sizing);
}

SurfacePacking CommandDomain::sample_surface(Rng& rng) const {
  return sample_mps(surface, *surface_sizing, rng);
}

SurfacePacking CommandDomain::read_surface(const std::string& csv, bool check) const {
  SurfacePacking packing = empty_surface_packing();
  with_flags("", [&] {
    read_surface_csv(csv, packing);
    if (check) validate_packing(packing, csv);
  });
  return packing;
}

}  // namespace disktune::cli
