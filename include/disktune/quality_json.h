// SPDX-License-Identifier: GPL-3.0-or-later
// The quality report as JSON, for pipelines to read. Keys and definitions in
// docs/quality.md; histograms are objects {lo, bin_width, counts, overflow}.
#pragma once

#include <string>

#include <cstdint>
#include <vector>

#include "disktune/fiber_statistics.h"
#include "disktune/quality.h"
#include "disktune/spectrum.h"

namespace disktune {

/// The report as a JSON document (two-space indented), with the key `spectrum` when a
/// spectrum is given (its summary: radial mean, anisotropy, peak, effective Nyquist).
std::string quality_json(const QualityReport& report, const Spectrum* spectrum = nullptr);

/// Writes quality_json(report, spectrum) to `path` through write_file_atomically.
void write_quality_json(const std::string& path, const QualityReport& report,
                        const Spectrum* spectrum = nullptr);

/// The planar-domain report: the density and checks, and `mesh`, `interior_triangles`
/// and `boundary_triangles`, each {vertex_count, triangle_count, interior_vertex_count,
/// angles, edges, local_beta} with the keys of the torus report.
std::string quality_json(const PlanarQualityReport& report);
void write_quality_json(const std::string& path, const PlanarQualityReport& report);

/// A surface mesh's measures: {vertex_count, triangle_count, interior_vertex_count,
/// hausdorff, angles, edges, local_beta} with the keys of the torus report.
std::string quality_json(const SurfaceMeshQuality& quality);
void write_quality_json(const std::string& path, const SurfaceMeshQuality& quality);

/// A fiber arrangement's statistics (docs/rve.md): `rve` {fibers, width, height,
/// diameter, gap, fiber_fraction, seed}, `statistics` (the fields of FiberStatistics),
/// `local_fraction` [{side_over_d, windows, fraction}] among them; `rsa` (the same for `sample`, the maximal sample the arrangement was tuned from:
/// random sequential adsorption to saturation, of the same fibers; omitted when null),
/// `csr` (complete spatial randomness at the same intensity: the k-th neighbour's mean
/// distance, K = pi r^2, L = r, g = 1, the Voronoi area CV) and `hexagonal` (the lattice
/// of the same count: all six neighbours at its spacing, psi6 1, CV 0).
std::string fiber_statistics_json(const FiberStatistics& fibers, const FiberStatistics* sample, double gap,
                                  std::uint64_t seed);
void write_fiber_statistics_json(const std::string& path, const FiberStatistics& fibers, const FiberStatistics* sample,
                                 double gap, std::uint64_t seed);
/// An ensemble of realizations (make_rves, seeds first_seed, first_seed + 1, ...): `rve`
/// (with `realizations`), `ensemble` (min, mean, max and stddev over the realizations of
/// global and local psi6, the hexagonal share, the Voronoi area CV, each neighbour's mean
/// distance and each window's local-fraction spread; the mean g(r) and K(r)),
/// `realizations` [{seed, statistics, rsa}] and the references `csr` and `hexagonal`.
/// `samples` is empty or holds one sample per realization. Throws InvalidInput for no
/// realization.
std::string fiber_ensemble_json(const std::vector<FiberStatistics>& fibers, const std::vector<FiberStatistics>& samples,
                                double gap, std::uint64_t first_seed);
void write_fiber_ensemble_json(const std::string& path, const std::vector<FiberStatistics>& fibers,
                               const std::vector<FiberStatistics>& samples, double gap, std::uint64_t first_seed);

}  // namespace disktune
