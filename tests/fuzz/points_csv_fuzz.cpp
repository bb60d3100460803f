// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: CSV x,y,r files of planar samples (read_points_csv), and the same
// read into a packing of the unit periodic box with r = 0.1, as `tune --input` reads them.
#include <cstddef>
#include <cstdint>

#include "disktune/io.h"
#include "disktune/periodic_box.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace disktune;
  static fuzz::InputFile file(".csv");
  static const PeriodicBox box(1.0, 1.0);
  const std::string& path = file.write(data, size);
  fuzz::expect_documented_errors([&] { read_points_csv(path); });
  fuzz::expect_documented_errors([&] { read_packing_csv(path, box, 0.1); });
  return 0;
}
