// SPDX-License-Identifier: GPL-3.0-or-later
// The simple sizing functions and parse_sizing, which tells the kinds of sizing apart in
// one text. Expressions and grid files have their own files.
#include "disktune/sizing.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../io/number_text.h"
#include "disktune/errors.h"
#include "sizing_text.h"

namespace disktune {
namespace {

using detail::number_text;
using detail::parse_number;
using detail::trimmed;

// The numbers after a "kind:" prefix, split at commas; refuses on a periodic box.
std::vector<std::string> boundary_args(const std::string& spec, const std::string& args, const char* what,
                                       const PlanarDomain* domain) {
  if (!domain) {
    throw InvalidInput("sizing \"" + spec + "\": " + what +
                           " needs a planar domain (on a periodic box there is "
                           "no boundary); give a planar domain, or use a number or an expression in x and y",
                       InvalidInput::Remedy::domain);
  }
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = args.find(',', start);
    parts.push_back(trimmed(args.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

Sizing parse_feature(const std::string& spec, const std::string& args, std::shared_ptr<const PlanarDomain> domain) {
  const std::vector<std::string> parts = boundary_args(spec, args, "feature sizing", domain.get());
  double r_max = 0, g = kFeatureGradation;
  if (parts.size() > 2 || !parse_number(parts[0], r_max) || (parts.size() == 2 && !parse_number(parts[1], g))) {
    throw InvalidInput("sizing \"" + spec + "\": expected auto:RMAX or auto:RMAX,G with numbers, e.g. auto:0.02");
  }
  return feature_sizing(std::move(domain), r_max, g);
}

Sizing parse_boundary(const std::string& spec, const std::string& args,
                      std::shared_ptr<const PlanarDomain> domain) {
  const std::vector<std::string> parts = boundary_args(spec, args, "boundary grading", domain.get());
  double v[3];
  if (parts.size() != 3 || !parse_number(parts[0], v[0]) || !parse_number(parts[1], v[1]) ||
      !parse_number(parts[2], v[2])) {
    throw InvalidInput("sizing \"" + spec +
                       "\": expected boundary:RMIN,RMAX,G with three numbers, e.g. "
                       "boundary:0.005,0.05,0.2");
  }
  return boundary_grading_sizing(std::move(domain), v[0], v[1], v[2]);
}

}  // namespace

Sizing constant_sizing(double r) {
  if (!std::isfinite(r) || !(r > 0)) {
    throw InvalidInput("a constant sizing r = " + number_text(r) +
                       " is not a finite positive radius; give r > 0");
  }
  return Sizing([r](Vec2) { return r; }, number_text(r));
}

Sizing boundary_grading_sizing(std::shared_ptr<const PlanarDomain> domain, double r_min,
                               double r_max, double g) {
  const std::string params = "r_min = " + number_text(r_min) + ", r_max = " + number_text(r_max) +
                             ", g = " + number_text(g);
  if (!domain) throw InvalidInput("boundary grading (" + params + ") needs a planar domain");
  if (!std::isfinite(r_min) || !std::isfinite(r_max) || !std::isfinite(g) || !(r_min > 0) ||
      !(r_min <= r_max) || !(g >= 0)) {
    throw InvalidInput("boundary grading with " + params +
                       " is not valid: it needs 0 < r_min <= r_max and g >= 0 (g is the "
                       "gradation; below 0.25 keeps the mesh angles well bounded)");
  }
  std::string description = "boundary grading min(" + number_text(r_max) + ", " +
                            number_text(r_min) + " + " + number_text(g) + " d)";
  return Sizing(
      [domain, r_min, r_max, g](Vec2 p) {
        return std::min(r_max, r_min + g * domain->distance_to_boundary(p));
      },
      std::move(description));
}

Sizing parse_sizing(const std::string& spec, std::shared_ptr<const PlanarDomain> domain) {
  const std::string text = detail::sizing_text(
      spec, "a radius (0.01), boundary:RMIN,RMAX,G, auto:RMAX, a grid file, or an expression in x and y (\"0.01 + 0.02*x\")");
  if (double r = 0; detail::constant_radius(text, r)) return constant_sizing(r);
  for (const std::string prefix : {"boundary:", "auto:"}) {
    if (text.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string args = text.substr(prefix.size());
    return prefix == "auto:" ? parse_feature(text, args, std::move(domain))
                             : parse_boundary(text, args, std::move(domain));
  }
  std::error_code ec;
  if (std::filesystem::is_regular_file(text, ec)) return grid_sizing(text);
  try {
    return expression_sizing(text);
  } catch (const InvalidInput& e) {
    // Most likely a mistyped file name: say so before the parser's complaint.
    if (text.find('/') != std::string::npos || text.find('\\') != std::string::npos) {
      throw InvalidInput("sizing \"" + text + "\": no such file, and as an expression: " + e.what());
    }
    throw;
  }
}

}  // namespace disktune
