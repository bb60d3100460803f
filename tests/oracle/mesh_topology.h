// SPDX-License-Identifier: GPL-3.0-or-later
//
// Independent test oracle for the topology of a triangle mesh (issue #15, item 2):
// written apart from the library, standard library only. A mesh is a 2-manifold when
// every edge lies in one or two triangles, the triangles around every vertex form one
// fan (a disk or, at the boundary, a half-disk), and the two triangles of an edge run it
// in opposite directions (consistently oriented). Its genus is the sum over connected
// components of (2 - V + E - F - b) / 2, b the component's boundary loops.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace oracle {

struct TopologyReport {
  std::size_t non_manifold_edges = 0;   // in three or more triangles
  std::size_t bow_tie_vertices = 0;     // whose triangles form more than one fan
  std::size_t misoriented_edges = 0;    // two triangles running it the same way
  std::size_t degenerate_triangles = 0; // a vertex named twice
  std::size_t boundary_edges = 0, boundary_loops = 0;
  std::size_t components = 0;           // through shared edges; unused vertices excluded
  int genus = -1;                       // -1 unless a manifold
  bool manifold() const {
    return non_manifold_edges == 0 && bow_tie_vertices == 0 && misoriented_edges == 0 && degenerate_triangles == 0;
  }
  std::string summary() const;
};

/// Throws std::invalid_argument for a vertex index >= vertex_count.
TopologyReport check_topology(std::size_t vertex_count, const std::vector<std::array<std::size_t, 3>>& triangles);

}  // namespace oracle
