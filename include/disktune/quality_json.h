// SPDX-License-Identifier: GPL-3.0-or-later
// The quality report as JSON, for pipelines to read. Keys and definitions in
// docs/quality.md; histograms are objects {lo, bin_width, counts, overflow}.
#pragma once

#include <string>

#include "disktune/quality.h"

namespace disktune {

/// The report as a JSON document (two-space indented).
std::string quality_json(const QualityReport& report);

/// Writes quality_json(report) to `path` through write_file_atomically.
void write_quality_json(const std::string& path, const QualityReport& report);

}  // namespace disktune
