// SPDX-License-Identifier: GPL-3.0-or-later
// remesh (disktune/remesh.h) from one CGAL::Surface_mesh into another. Header-only:
// include it where CGAL is at hand.
#pragma once

#include <CGAL/Surface_mesh.h>

#include <cstddef>

#include "disktune/cgal/mesh_output.h"
#include "disktune/cgal/surface_from_cgal.h"
#include "disktune/remesh.h"

namespace disktune {

/// Remeshes the triangle mesh `in` into `out` (which may be `in`) with exactly
/// `vertex_count` vertices. The result's `mesh` holds the same mesh as plain arrays.
/// Throws as remesh and copy_into do; `out` is left as it was then.
template <class P>
RemeshResult remesh(const CGAL::Surface_mesh<P>& in, std::size_t vertex_count, CGAL::Surface_mesh<P>& out,
                    const RemeshOptions& options = {}) {
  RemeshResult result = remesh(surface_domain_from(in), vertex_count, options);
  copy_into(result.mesh, out);
  return result;
}

}  // namespace disktune
