// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/remesh.h"

#include <string>
#include <vector>

#include "../domain/radius_limits.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/surface_tuning.h"

namespace disktune {

RemeshResult remesh(std::shared_ptr<const SurfaceDomain> surface, std::size_t vertex_count,
                    const RemeshOptions& options) {
  if (!surface) throw InvalidInput("remesh: no surface given");
  if (vertex_count < 4) {
    throw InvalidInput("remesh: a surface mesh needs at least 4 vertices, " + std::to_string(vertex_count) +
                       " asked for");
  }
  RemeshResult out;
  out.radius = radius_for_count(vertex_count, surface->area(), options.area_fraction);
  try {
    detail::check_radius_for_area(out.radius, surface->area(), "this surface");
  } catch (const InvalidInput& e) {
    throw InvalidInput("remesh: " + std::to_string(vertex_count) + " vertices are too many: " + e.what());
  }
  Rng rng(options.seed);
  SurfacePacking packing = sample_mps(surface, SurfaceSizing::constant(out.radius), rng);
  out.tuning = tune(packing, Target::count(vertex_count), rng, options.tune);

  std::vector<Vec3> samples;
  samples.reserve(packing.size());
  for (const DiskId id : packing.ids()) samples.push_back(packing.center(id));
  out.mesh = restricted_delaunay(samples, *surface);
  out.check = check_surface_mesh(out.mesh);
  return out;
}

RemeshResult remesh(const SurfaceDomain& surface, std::size_t vertex_count, const RemeshOptions& options) {
  return remesh(std::make_shared<const SurfaceDomain>(surface), vertex_count, options);
}

}  // namespace disktune
