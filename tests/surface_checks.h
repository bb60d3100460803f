// SPDX-License-Identifier: GPL-3.0-or-later
// Glue between surface packings and the independent surface oracle.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "disktune/surface_packing.h"
#include "oracle/surface_oracle.h"

namespace disktune::test {

inline std::shared_ptr<const SurfaceDomain> surface_file(const std::string& name) {
  return std::make_shared<const SurfaceDomain>(read_surface(std::string(DISKTUNE_DATA_DIR) + "/surfaces/" + name));
}

inline oracle::SurfaceMeshInput oracle_surface(const SurfaceDomain& d) {
  oracle::SurfaceMeshInput m;
  for (const Vec3 v : d.vertices()) m.vertices.push_back({v.x, v.y, v.z});
  for (const auto& t : d.triangles()) m.triangles.push_back({t[0], t[1], t[2]});
  return m;
}

/// The oracle's verdict on a surface packing; the fixed disks are the boundary disks.
inline oracle::SurfaceReport surface_report(const SurfacePacking& packing, std::size_t probes_per_triangle = 8) {
  std::vector<oracle::Point3> centers;
  std::vector<double> radii;
  oracle::SurfaceOptions options;
  options.probes_per_triangle = probes_per_triangle;
  for (const DiskId id : packing.ids()) {
    const Vec3 c = packing.center(id);
    centers.push_back({c.x, c.y, c.z});
    radii.push_back(packing.radius(id));
    options.boundary_flags.push_back((packing.flags(id) & kFixed) ? 1 : 0);
  }
  if (packing.domain().is_closed()) options.boundary_flags.clear();
  return oracle::check_surface(oracle_surface(packing.domain()), centers, radii, options);
}

/// Checks the oracle's verdict, with its summary as the failure message.
#define EXPECT_SURFACE_OK(packing)                                   \
  do {                                                               \
    const auto report_ = ::disktune::test::surface_report(packing); \
    EXPECT_TRUE(report_.ok()) << report_.summary();                  \
  } while (0)

}  // namespace disktune::test
