// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: sizing grid files (grid_sizing), evaluated inside, on and far outside
// any grid, where it is clamped.
#include <cstddef>
#include <cstdint>
#include <limits>

#include "disktune/sizing.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace disktune;
  static fuzz::InputFile file(".txt");
  const std::string& path = file.write(data, size);
  fuzz::expect_documented_errors([&] {
    const Sizing r = grid_sizing(path);
    const double big = std::numeric_limits<double>::max();
    for (const Vec2 p : {Vec2{0, 0}, Vec2{0.5, 0.5}, Vec2{1, 1}, Vec2{-3, 7}, Vec2{1e12, -1e12},
                         Vec2{big, -big}, Vec2{std::numeric_limits<double>::quiet_NaN(), 0}}) {
      r(p);
    }
  });
  return 0;
}
