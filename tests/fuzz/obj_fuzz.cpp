// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: .obj files (mesh_fuzz.h).
#include "mesh_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  disktune::fuzz::fuzz_mesh_file(data, size, ".obj");
  return 0;
}
