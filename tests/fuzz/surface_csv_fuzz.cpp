// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: CSV x,y,z,r (or x,y,z) files of surface samples (read_surface_csv),
// read onto an open unit box (fuzz_util.h) with r = 0.25.
#include <cstddef>
#include <cstdint>

#include "disktune/surface_io.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_sizing.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace disktune;
  static fuzz::InputFile file(".csv");
  static const auto domain = fuzz::open_box();
  const std::string& path = file.write(data, size);
  fuzz::expect_documented_errors([&] {
    SurfacePacking packing(domain, SurfaceSizing::constant(0.25));
    read_surface_csv(path, packing);
  });
  return 0;
}
