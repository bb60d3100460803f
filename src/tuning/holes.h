// SPDX-License-Identifier: GPL-3.0-or-later
// The holes of a packing in a periodic box (internal): the vertices of its Voronoi
// diagram, which are the centers of its Delaunay triangles' empty circles, widest circle
// first. Squeeze injection puts new disks there, where they overlap their neighbours
// least.
#pragma once

#include <vector>

#include "disktune/packing.h"

namespace disktune::detail {

/// Every Voronoi vertex of the packing (one per Delaunay triangle, wrapped into the
/// box), the widest empty circle first, ties in a fixed order. A maximal packing with
/// one radius r in a box at least 4.5 r wide each way has each disk's Voronoi cell
/// within r of its center, bounded by the disks within 2r: the cells are made one disk
/// at a time on up to `threads` threads, each vertex kept by the smallest id of its three
/// disks (the same holes on any number of threads). Otherwise (some cell reaching past
/// 1.005 r: the packing is not maximal there) they come from periodic_delaunay. Near-degenerate
/// vertices (four disks on one circle, to rounding) may come twice or not at all: the
/// holes only guide where new disks start.
std::vector<Vec2> holes_largest_first(const Packing& packing, unsigned threads);

/// The same from periodic_delaunay's triangles, in their order where circles are equal:
/// what holes_largest_first falls back to, and what tests compare it with.
std::vector<Vec2> delaunay_holes_largest_first(const Packing& packing);

}  // namespace disktune::detail
