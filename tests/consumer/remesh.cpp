// SPDX-License-Identifier: GPL-3.0-or-later
// A program written against the installed library (tests/consumer_test.sh builds it):
//   consumer INPUT.off N OUTPUT.off
// remeshes the surface to exactly N vertices in one call. The same code is built into a
// shared library (with REMESH_PLUGIN: no main) to check that a static libdisktune links
// into one.
#include <disktune/disktune.h>

#include <cstdio>
#include <exception>
#include <string>

int remesh_main(int argc, char** argv) {
  if (argc != 4) return std::fprintf(stderr, "usage: %s INPUT N OUTPUT\n", argv[0]), 2;
  try {
    const std::size_t n = std::stoul(argv[2]);
    const disktune::RemeshResult result = disktune::remesh(disktune::read_surface(argv[1]), n);
    if (result.mesh.vertices.size() != n) return std::fprintf(stderr, "not %zu vertices\n", n), 4;
    disktune::write_surface_mesh(argv[3], result.mesh);
    return 0;
  } catch (const std::exception& e) {
    return std::fprintf(stderr, "%s: %s\n", argv[0], e.what()), 1;
  }
}

#ifndef REMESH_PLUGIN
int main(int argc, char** argv) { return remesh_main(argc, argv); }
#endif
