// SPDX-License-Identifier: GPL-3.0-or-later
#include "python_packing.h"

#include <cmath>

namespace disktune::python {

namespace py = pybind11;

py::array_t<double> PyPacking::points() const {
  const std::vector<DiskId> all = ids();
  const py::ssize_t columns = plane ? 2 : 3;
  py::array_t<double> out({static_cast<py::ssize_t>(all.size()), columns});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    if (plane) {
      const Vec2 c = plane->center(all[i]);
      a(i, 0) = c.x, a(i, 1) = c.y;
    } else {
      const Vec3 c = surface->center(all[i]);
      a(i, 0) = c.x, a(i, 1) = c.y, a(i, 2) = c.z;
    }
  }
  return out;
}

std::vector<double> PyPacking::radii() const {
  std::vector<double> out;
  for (const DiskId id : ids()) out.push_back(plane ? plane->radius(id) : surface->radius(id));
  return out;
}

std::vector<bool> PyPacking::fixed() const {
  std::vector<bool> out;
  for (const DiskId id : ids())
    out.push_back(((plane ? plane->flags(id) : surface->flags(id)) & kFixed) != 0);
  return out;
}

std::unordered_map<DiskId, std::int64_t> PyPacking::rows() const {
  std::unordered_map<DiskId, std::int64_t> out;
  std::int64_t row = 0;
  for (const DiskId id : ids()) out[id] = row++;
  return out;
}

bool PyPacking::is_maximal() const {
  return plane ? disktune::is_maximal(*plane) : disktune::is_maximal(*surface);
}

bool PyPacking::is_conflict_free() const {
  return plane ? disktune::is_conflict_free(*plane) : disktune::is_conflict_free(*surface);
}

void PyPacking::write_csv(const std::string& path) const {
  plane ? write_points_csv(path, *plane) : write_surface_csv(path, *surface);
}

namespace {

// The radius r where it fits the domain, else (as the command does) the sizing that
// shrinks it near the features that are too close for it, with a note saying so.
void sample_plane(PyPacking& out, const Domain& where, std::optional<double> radius,
                  const std::optional<std::string>& spec, Rng& rng) {
  std::shared_ptr<const Sizing> sizing;
  if (spec) {
    sizing = std::make_shared<const Sizing>(parse_sizing(*spec, where.planar));
  } else if (where.planar && std::isfinite(*radius) && *radius > 0 &&
             !where.planar->corners_fit(*radius)) {
    sizing = std::make_shared<const Sizing>(feature_sizing(where.planar, *radius));
    out.note = "r = " + std::to_string(*radius) +
               " does not fit this domain (two of its corners are closer than r): sampled with the "
               "sizing auto:" +
               std::to_string(*radius) + ", which shrinks r near small features";
  }
  if (sizing) {
    const Frame& frame = where.box ? where.box->frame() : where.planar->frame();
    check_gradation(measure_sizing(*sizing, frame, where.planar.get()));
    out.need = where.box ? estimate_resources(*where.box, *sizing)
                         : estimate_resources(*where.planar, *sizing);
    check_resources(out.need, available_memory());
    out.plane =
        where.box ? sample_mps(*where.box, sizing, rng) : sample_mps(where.planar, sizing, rng);
  } else {
    out.need = where.box ? estimate_resources(*where.box, *radius)
                         : estimate_resources(*where.planar, *radius);
    check_resources(out.need, available_memory());
    out.plane =
        where.box ? sample_mps(*where.box, *radius, rng) : sample_mps(where.planar, *radius, rng);
  }
  out.unit = density_unit(*out.plane, where.box ? where.box->area() : where.planar->area());
}

void sample_surface(PyPacking& out, const Domain& where, std::optional<double> radius,
                    const std::optional<std::string>& spec, Rng& rng) {
  const SurfaceDomain& surface = *where.surface;
  SurfaceSizing sizing =
      spec ? parse_surface_sizing(*spec, surface) : SurfaceSizing::constant(*radius);
  if (!spec && !curves_fit(surface, *radius)) {
    sizing = thickness_sizing(surface, *radius);
    out.note = "r = " + std::to_string(*radius) +
               " does not fit this surface (two of its feature curves or boundaries are closer "
               "than r along "
               "more than 3r): sampled with the sizing auto:" +
               std::to_string(*radius) + ", which shrinks r near them";
  }
  out.need = estimate_resources(surface, sizing);
  check_resources(out.need, available_memory());
  out.surface = sample_mps(where.surface, sizing, rng);
  out.unit = density_unit(*out.surface);
}

}  // namespace

PyPacking sample(const Domain& where, std::optional<double> radius,
                 const std::optional<std::string>& sizing, Rng& rng) {
  PyPacking out;
  out.box = where.box, out.planar = where.planar;
  if (where.surface) {
    sample_surface(out, where, radius, sizing, rng);
  } else {
    sample_plane(out, where, radius, sizing, rng);
  }
  return out;
}

TuneResult tune(PyPacking& packing, const Target& target, Rng& rng, const TuneOptions& options) {
  if (packing.surface) {
    check_resources(
        packing.need.tuned_to(static_cast<double>(target_count(target, *packing.surface))),
        available_memory());
    return disktune::tune(*packing.surface, target, rng, options);
  }
  Packing& plane = *packing.plane;
  const double boundary =
      packing.planar ? boundary_unit(*packing.planar, plane.sizing(), plane.max_radius()) : 0;
  check_resources(packing.need.tuned_to(
                      static_cast<double>(target_count_for_unit(target, packing.unit, boundary))),
                  available_memory());
  return packing.box ? disktune::tune(plane, *packing.box, target, rng, options)
                     : disktune::tune(plane, *packing.planar, target, rng, options);
}

}  // namespace disktune::python
