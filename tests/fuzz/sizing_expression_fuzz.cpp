// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: sizing specifications as text (no file): the planar expression
// (expression_sizing, evaluated at a few points), the command line's parse_sizing with a
// planar domain (numbers, boundary:RMIN,RMAX,G), and the surface's parse_surface_sizing
// (expressions in x, y, z, curvature[:RMIN,RMAX]) on an open unit box.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "disktune/planar_domain.h"
#include "disktune/sizing.h"
#include "disktune/surface_sizing.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace disktune;
  static const auto surface = fuzz::open_box();
  static const auto square = std::make_shared<const PlanarDomain>(
      std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, std::vector<std::vector<Vec2>>{});
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expect_documented_errors([&] {
    const Sizing r = expression_sizing(text);
    for (const Vec2 p : {Vec2{0, 0}, Vec2{0.5, 0.25}, Vec2{-1, 1e6}}) r(p);
  });
  // parse_sizing reads a text that names an existing file as a grid file: that reader
  // has its own target, and this one stays off the file system.
  std::error_code ec;
  if (!std::filesystem::exists(text, ec)) {
    fuzz::expect_documented_errors([&] {
      const Sizing r = parse_sizing(text, square);
      for (const Vec2 p : {Vec2{0, 0}, Vec2{0.5, 0.25}, Vec2{2, -1}}) r(p);
    });
  }
  fuzz::expect_documented_errors([&] { parse_surface_sizing(text, *surface); });
  return 0;
}
