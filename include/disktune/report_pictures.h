// SPDX-License-Identifier: GPL-3.0-or-later
// The quality report as PNG pictures, for a person to look at: the power spectrum, its
// radial mean and anisotropy, and the angle and edge-length histograms.
#pragma once

#include <string>

#include "disktune/quality.h"
#include "disktune/spectrum.h"

namespace disktune {

/// Writes into the existing folder `dir`: angles.png and edges.png (histograms of the
/// report) and, when a spectrum is given, spectrum.png (log10 P from -2 black to 1
/// white, DC at the center, ky up), radial_mean.png and anisotropy.png (line plots over
/// normalised frequency, dashed gray references at 1 and 0 dB, y cut at 4 and +-30 dB). Every picture is drawn
/// before any file is written, and each file is written atomically. Throws IoError when
/// `dir` is not an existing folder (nothing written) or a file cannot be written.
void write_report_pictures(const std::string& dir, const QualityReport& report,
                           const Spectrum* spectrum = nullptr);

/// Throws IoError unless `dir` is an existing folder: front ends call it before any
/// work, so a typo costs no minutes of computing.
void check_picture_folder(const std::string& dir);

}  // namespace disktune
