// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh file readers (OFF, OBJ, PLY, STL): the polygon soup every reader gives, the
// surface built from it (read_surface validates the manifold), and for a flat OFF or OBJ
// file the planar domain of its boundary loops, as the command reads a --domain file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "../../src/io/polygon_soup.h"
#include "disktune/planar_domain.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_io.h"
#include "fuzz_util.h"

namespace disktune::fuzz {

inline void fuzz_mesh_file(const std::uint8_t* data, std::size_t size,
                           const std::string& extension) {
  static InputFile file(extension);
  const std::string& path = file.write(data, size);
  expect_documented_errors([&] { detail::read_polygon_soup(path); });
  expect_documented_errors([&] { read_surface(path); });
  if (extension == ".off" || extension == ".obj") {
    expect_documented_errors([&] {
      if (is_flat_mesh_file(path)) read_planar_domain(path);
    });
  }
}

}  // namespace disktune::fuzz
