// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/remesh.h"

#include <string>
#include <vector>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/resources.h"
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
  const SurfaceSizing sizing = SurfaceSizing::constant(out.radius);
  try {
    const ResourceEstimate need =
        estimate_resources(*surface, sizing).tuned_to(static_cast<double>(vertex_count));
    check_resources(need, options.max_memory > 0 ? options.max_memory : available_memory());
  } catch (const InvalidInput& e) {
    throw InvalidInput("remesh: " + std::to_string(vertex_count) + " vertices are too many: " + e.what(),
                       e.remedy());
  }
  Rng rng(options.seed);
  SurfacePacking packing = sample_mps(surface, sizing, rng);
  out.tuning = tune(packing, Target::count(vertex_count), rng, options.tune);

  out.mesh = restricted_delaunay(packing);
  out.check = check_surface_mesh(out.mesh);
  return out;
}

RemeshResult remesh(const SurfaceDomain& surface, std::size_t vertex_count, const RemeshOptions& options) {
  return remesh(std::make_shared<const SurfaceDomain>(surface), vertex_count, options);
}

}  // namespace disktune
