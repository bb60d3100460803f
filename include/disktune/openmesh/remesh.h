// SPDX-License-Identifier: GPL-3.0-or-later
// remesh (disktune/remesh.h) from one OpenMesh mesh into another. Header-only: include
// it where OpenMesh is at hand.
#pragma once

#include <cstddef>

#include "disktune/openmesh/mesh_output.h"
#include "disktune/openmesh/surface_from_openmesh.h"
#include "disktune/remesh.h"

namespace disktune {

/// Remeshes the triangle mesh `in` into `out` (which may be `in`; an OpenMesh TriMesh or
/// PolyMesh) with exactly `vertex_count` vertices. Throws as remesh and copy_into do;
/// `out` is left as it was then.
template <class OpenMeshMesh>
RemeshResult remesh(const OpenMeshMesh& in, std::size_t vertex_count, OpenMeshMesh& out,
                    const RemeshOptions& options = {}) {
  RemeshResult result = remesh(surface_domain_from(in), vertex_count, options);
  copy_into(result.mesh, out);
  return result;
}

}  // namespace disktune
