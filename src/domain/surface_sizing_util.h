// SPDX-License-Identifier: GPL-3.0-or-later
// What the surface sizings share (internal): vertices in messages, the vertex graph of
// the mesh's edges, and (number_text.h) the number text of descriptions.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "../io/number_text.h"
#include "point_text.h"
#include "disktune/surface_domain.h"

namespace disktune::detail {

/// "vertex 12 at (0.1, 0.2, 0.3)", every digit.
inline std::string vertex_text(const SurfaceDomain& domain, std::size_t v) {
  return "vertex " + std::to_string(v) + " at " + point_text(domain.vertices()[v]);
}

/// Each vertex's neighbours along the mesh's edges, sorted, each once.
inline std::vector<std::vector<std::size_t>> vertex_neighbours(const SurfaceDomain& domain) {
  std::vector<std::vector<std::size_t>> out(domain.vertices().size());
  for (const auto& t : domain.triangles()) {
    for (int k = 0; k < 3; ++k) {
      out[t[k]].push_back(t[(k + 1) % 3]);
      out[t[k]].push_back(t[(k + 2) % 3]);
    }
  }
  for (auto& n : out) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return out;
}

}  // namespace disktune::detail
