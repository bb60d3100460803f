// SPDX-License-Identifier: GPL-3.0-or-later
// What the Python module hands out as disktune.Packing: a packing of the periodic box, a
// planar domain or a surface, with its domain, and the calls that depend on which.
#pragma once

#include <pybind11/numpy.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "disktune/disktune.h"

namespace disktune::python {

// Python's PlanarDomain and Surface: shared, so that packings keep them alive.
struct PlanarHandle {
  std::shared_ptr<const PlanarDomain> domain;
};
struct SurfaceHandle {
  std::shared_ptr<const SurfaceDomain> domain;
};

// Where a packing lives: exactly one of the three.
struct Domain {
  std::optional<PeriodicBox> box;
  std::shared_ptr<const PlanarDomain> planar;
  std::shared_ptr<const SurfaceDomain> surface;
};

struct PyPacking {
  std::optional<PeriodicBox> box;
  std::shared_ptr<const PlanarDomain> planar;
  std::optional<Packing> plane;           // box or planar domain
  std::optional<SurfacePacking> surface;  // on a surface
  double unit = 0;                        // disks at area fraction 1 (density_unit)
  std::optional<TuneResult> tuning;       // set by tune()
  ResourceEstimate need;                  // the sample's, for the memory guard of tune()
  std::string note;                       // a radius that did not fit, and what was done

  std::size_t size() const { return plane ? plane->size() : surface->size(); }
  std::vector<DiskId> ids() const { return plane ? plane->ids() : surface->ids(); }
  pybind11::array_t<double> points() const;
  std::vector<double> radii() const;
  std::vector<bool> fixed() const;
  double area_fraction() const { return static_cast<double>(size()) / unit; }
  /// Each disk's row in points() and radii().
  std::unordered_map<DiskId, std::int64_t> rows() const;
  bool is_maximal() const;
  bool is_conflict_free() const;
  void write_csv(const std::string& path) const;
};

/// A maximal sample of the domain with one radius or a sizing spec (the command's
/// --sizing), after the same memory guard as the command's.
PyPacking sample(const Domain& where, std::optional<double> radius,
                 const std::optional<std::string>& sizing, Rng& rng);

/// Tunes `packing` in place.
TuneResult tune(PyPacking& packing, const Target& target, Rng& rng, const TuneOptions& options);

}  // namespace disktune::python
