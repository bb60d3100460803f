// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: Triangle's .poly files (read_poly), then the first queries a domain
// answers (inside, distance to the boundary, the radius check) at its corners and center.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "disktune/planar_domain.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace disktune;
  static fuzz::InputFile file(".poly");
  const std::string& path = file.write(data, size);
  fuzz::expect_documented_errors([&] {
    const PlanarDomain domain = read_poly(path);
    const Frame& f = domain.frame();
    for (const Vec2 p :
         {f.origin, f.origin + f.extent, f.origin + f.extent * 0.5, domain.loops()[0][0]}) {
      domain.contains(p);
      domain.distance_to_boundary(p);
    }
    domain.validate_radius(0.01 * std::max(f.extent.x, f.extent.y));
  });
  return 0;
}
