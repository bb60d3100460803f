// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: Triangle's .poly files (read_poly), then the first queries a domain
// answers (inside, distance to the boundary, the radius checks, the local feature size
// sizing) at its corners and center.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "disktune/planar_domain.h"
#include "disktune/sizing.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace disktune;
  static fuzz::InputFile file(".poly");
  const std::string& path = file.write(data, size);
  fuzz::expect_documented_errors([&] {
    const auto domain = std::make_shared<const PlanarDomain>(read_poly(path));
    const Frame& f = domain->frame();
    const double r = 0.01 * std::max(f.extent.x, f.extent.y);
    const Sizing sizing = feature_sizing(domain, r);
    for (const Vec2 p :
         {f.origin, f.origin + f.extent, f.origin + f.extent * 0.5, domain->loops()[0][0]}) {
      domain->contains(p);
      domain->distance_to_boundary(p);
      if (!(sizing(p) > 0 && sizing(p) <= r)) std::abort();  // a radius in (0, r] everywhere
    }
    domain->corners_fit(r);
    domain->validate_radius(r);
  });
  return 0;
}
