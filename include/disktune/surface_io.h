// SPDX-License-Identifier: GPL-3.0-or-later
// Files of surface samples: CSV with header `x,y,z,r`, written atomically like the planar
// `x,y,r` files (io.h); and how to tell a flat mesh file (a planar domain) from a curved one.
#pragma once

#include <string>

#include "disktune/surface_packing.h"

namespace disktune {

/// CSV with header `x,y,z,r`, one live disk a line in id order, each number in the
/// shortest form that reads back to the same double (at most 17 significant digits),
/// through write_file_atomically. Throws IoError when the file cannot be written.
void write_surface_csv(const std::string& path, const SurfacePacking& packing);

/// Reads a CSV of disk centers on the packing's surface into `packing` (made with its
/// domain and sizing): header `x,y,z,r` or `x,y,z` (the radius then comes from the
/// sizing). Each point goes into the triangle whose closest point is nearest, moved onto
/// that closest point; a point on an open boundary edge (within 1e-9 r) becomes a fixed
/// disk (kFixed), as sample_mps makes them. Throws InvalidInput naming the line
/// when a point lies farther than 1e-6 r from the surface, when a radius differs from
/// the sizing's by more than 1e-6 relative, or when the file holds no disks; IoError when
/// it cannot be read. No conflict or maximality check (validate_packing).
void read_surface_csv(const std::string& path, SurfacePacking& packing);

/// True when every vertex of the mesh file (.off, .obj, .ply, .stl, read as for
/// read_surface) has the same z, up to 1e-9 of its extent in x and y: the rule
/// read_planar_domain uses for a flat mesh. Throws IoError when it cannot be read.
bool is_flat_mesh_file(const std::string& path);

}  // namespace disktune
