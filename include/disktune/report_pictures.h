// SPDX-License-Identifier: GPL-3.0-or-later
// The quality report as pictures, for a person to look at: the power spectrum, its
// radial mean and anisotropy, and the angle and edge-length histograms; and a fiber
// arrangement's cell and statistics. PNG by default; PDF or SVG (vectors, real text) for
// papers and slides.
#pragma once

#include <string>

#include "disktune/fiber_statistics.h"
#include "disktune/packing.h"
#include "disktune/quality.h"
#include "disktune/spectrum.h"

namespace disktune {

/// The pictures' file format; the files are named as below with the format's extension
/// (angles.pdf for angles.png). PDF and SVG pages measure one point per PNG pixel.
enum class PictureFormat { png, pdf, svg };

/// "png", "pdf" or "svg".
std::string extension(PictureFormat format);

/// Writes into the existing folder `dir`: angles.png and edges.png (histograms of the
/// report) and, when a spectrum is given, spectrum.png (log10 P from -2 black to 1
/// white, DC at the center, ky up), radial_mean.png and anisotropy.png (line plots over
/// normalised frequency, dashed gray references at 1 and 0 dB, y cut at 4 and +-30 dB);
/// when the packing measured is given, orientation.png (its disks at half their radius,
/// 800 pixels across, each locally hexagonal one colored by its lattice orientation
/// around the color wheel over 60 degrees, the others light gray; a title above, the
/// hues' legend below). Every picture is drawn
/// before any file is written, and each file is written atomically. Throws IoError when
/// `dir` is not an existing folder (nothing written) or a file cannot be written.
void write_report_pictures(const std::string& dir, const QualityReport& report,
                           const Spectrum* spectrum = nullptr, const Packing* packing = nullptr,
                           PictureFormat format = PictureFormat::png);
/// The same for a planar domain's report: angles.png and edges.png (over all triangles)
/// and orientation.png of the packing measured (its frame 800 pixels across).
void write_report_pictures(const std::string& dir, const PlanarQualityReport& report,
                           const Packing& packing, PictureFormat format = PictureFormat::png);
/// The same for a surface mesh: surface.png (the mesh seen from the direction (1, 1, 1),
/// 800 pixels across, each triangle shaded and colored by its smallest angle, red at 30
/// degrees or less through yellow to green at 60, with a color bar), angles.png and
/// edges.png.
void write_report_pictures(const std::string& dir, const SurfaceMeshQuality& quality,
                           const SurfaceMesh& mesh, PictureFormat format = PictureFormat::png);

/// Writes into the existing folder `dir`: cell.png (the cell, 800 pixels across its width,
/// fiber i a blue disk of diameter diameters[i], those cut by a side completed by their
/// periodic images),
/// pair_correlation.png (g over r / D, reference 1) and ripley_l.png (L(r) - r over r / D,
/// reference 0), each in blue and, when `sample` is given (the arrangement's maximal
/// sample: random sequential adsorption), its curve in orange; nearest.png (histogram of
/// the nearest neighbour's distance over D) and psi6_local.png (histogram of local
/// abs(psi6)). Drawn before any file is written; each written atomically. Throws IoError
/// as write_report_pictures does.
void write_fiber_pictures(const std::string& dir, const PeriodicBox& cell,
                          const std::vector<Vec2>& centers, const std::vector<double>& diameters,
                          const FiberStatistics& stats, const FiberStatistics* sample = nullptr,
                          PictureFormat format = PictureFormat::png);

/// Throws IoError unless `dir` is an existing folder: front ends call it before any
/// work, so a typo costs no minutes of computing.
void check_picture_folder(const std::string& dir);

}  // namespace disktune
