// SPDX-License-Identifier: GPL-3.0-or-later
// Surface samples as CSV (x,y,z,r): round trips, boundary disks found again, refusals
// that name the line; and telling flat mesh files from curved ones.
#include "disktune/surface_io.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "disktune/errors.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::message_of;
using test::TempDir;

std::string data(const std::string& name) { return std::string(DISKTUNE_DATA_DIR) + "/" + name; }

std::shared_ptr<const SurfaceDomain> surface(const std::string& name) {
  return std::make_shared<const SurfaceDomain>(read_surface(data("surfaces/" + name)));
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(SurfaceCsv, RoundTripKeepsPointsRadiiAndBoundaryDisks) {
  TempDir dir;
  const auto domain = surface("mesh_with_border.off");
  Rng rng(5);
  const SurfacePacking a = sample_mps(domain, SurfaceSizing::constant(4), rng);
  write_surface_csv(dir.file("a.csv"), a);
  EXPECT_EQ(read_text(dir.file("a.csv")).substr(0, 8), "x,y,z,r\n");

  SurfacePacking b(domain, SurfaceSizing::constant(4));
  read_surface_csv(dir.file("a.csv"), b);
  ASSERT_EQ(b.size(), a.size());
  const auto ia = a.ids(), ib = b.ids();
  std::size_t fixed = 0;
  for (std::size_t k = 0; k < ia.size(); ++k) {
    EXPECT_LE(norm(a.center(ia[k]) - b.center(ib[k])), 1e-12);
    EXPECT_EQ(a.radius(ia[k]), b.radius(ib[k]));
    EXPECT_EQ(a.flags(ia[k]) & kFixed, b.flags(ib[k]) & kFixed) << "disk " << k;
    fixed += (b.flags(ib[k]) & kFixed) != 0;
  }
  EXPECT_GT(fixed, 0u);
  EXPECT_NO_THROW(validate_packing(b, "a.csv"));

  // Written again, the file reads back to the same points.
  write_surface_csv(dir.file("b.csv"), b);
  SurfacePacking c(domain, SurfaceSizing::constant(4));
  read_surface_csv(dir.file("b.csv"), c);
  EXPECT_EQ(c.size(), b.size());
}

TEST(SurfaceCsv, RadiusColumnMayBeLeftOut) {
  TempDir dir;
  const auto domain = surface("sphere.off");
  const Vec3 v = domain->vertices()[0];
  std::ostringstream text;
  text.precision(17);
  text << "x,y,z\n" << v.x << ',' << v.y << ',' << v.z << '\n';
  write_text(dir.file("p.csv"), text.str());
  SurfacePacking p(domain, SurfaceSizing::constant(0.1));
  read_surface_csv(dir.file("p.csv"), p);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p.radius(p.ids()[0]), 0.1);
}

TEST(SurfaceCsv, RefusalsNameTheLine) {
  TempDir dir;
  const auto domain = surface("sphere.off");
  const Vec3 v = domain->vertices()[0], w = domain->vertices()[1];
  auto row = [](Vec3 p, double r) {
    std::ostringstream s;
    s.precision(17);
    s << p.x << ',' << p.y << ',' << p.z << ',' << r << '\n';
    return s.str();
  };
  const std::pair<std::string, std::string> cases[] = {
      {"x,y,r\n", ":1: expected the header 'x,y,z,r' or 'x,y,z'"},
      {"x,y,z,r\n", "holds no disks"},
      {"x,y,z,r\n" + row(v, 0.1) + "1,2\n", ":3: expected four"},
      {"x,y,z,r\n" + row(v, 0.1) + row(v * 1.5, 0.1), ":3: point"},
      {"x,y,z,r\n" + row(v, 0.1) + row(w, 0.2), ":3: radius 0.2 differs"},
      {"x,y,z,r\n" + row(v, -1), ":2: radius must be positive"},
  };
  for (const auto& [text, where] : cases) {
    write_text(dir.file("bad.csv"), text);
    SurfacePacking p(domain, SurfaceSizing::constant(0.1));
    const std::string msg = message_of([&] { read_surface_csv(dir.file("bad.csv"), p); });
    EXPECT_NE(msg.find(where), std::string::npos) << msg;
  }
  // The radius differs: the message gives the samples' radius, and names the radius as
  // what to change (the command line adds --radius).
  write_text(dir.file("bad.csv"), "x,y,z,r\n" + row(v, 0.2));
  try {
    SurfacePacking q(domain, SurfaceSizing::constant(0.1));
    read_surface_csv(dir.file("bad.csv"), q);
    ADD_FAILURE() << "accepted a radius of 0.2 for 0.1";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("give the radius the samples were made with, 0.2"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.remedy(), InvalidInput::Remedy::radius);
    EXPECT_EQ(e.value(), "0.2");
  }
  SurfacePacking p(domain, SurfaceSizing::constant(0.1));
  EXPECT_THROW(read_surface_csv(dir.file("missing.csv"), p), IoError);
}

TEST(SurfaceCsv, FlatMeshFiles) {
  EXPECT_TRUE(is_flat_mesh_file(data("domains/square_with_hole.off")));
  EXPECT_FALSE(is_flat_mesh_file(data("surfaces/eight.off")));
  EXPECT_FALSE(is_flat_mesh_file(data("surfaces/mesh_with_border.off")));
  EXPECT_THROW(is_flat_mesh_file(data("surfaces/missing.off")), IoError);
}

}  // namespace
}  // namespace disktune
