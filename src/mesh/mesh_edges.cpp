// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/mesh.h"

namespace disktune {

std::vector<std::array<std::uint32_t, 2>> unique_edges(const TriangleMesh& mesh) {
  // A torus edge is two opposite half-edges u->v and v'->u' of two triangles; the copy
  // u->v is kept when its disks are in increasing order or, for an edge between two
  // copies of one disk, when the offset from u to v is lexicographically positive.
  std::vector<std::array<std::uint32_t, 2>> edges;
  edges.reserve(3 * mesh.disk_count);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[k], v = t[(k + 1) % 3];
      const DiskId du = mesh.vertex_disk[u], dv = mesh.vertex_disk[v];
      const std::int32_t ox = mesh.vertex_offset[v][0] - mesh.vertex_offset[u][0];
      const std::int32_t oy = mesh.vertex_offset[v][1] - mesh.vertex_offset[u][1];
      if (du < dv || (du == dv && (ox > 0 || (ox == 0 && oy > 0)))) edges.push_back({u, v});
    }
  }
  return edges;
}

}  // namespace disktune
