// SPDX-License-Identifier: GPL-3.0-or-later
// The report's PNG pictures: decoded here with libpng, of the expected size and not
// blank; a missing folder is refused before anything is written. The fiber cell's
// picture: its blue pixels are where the fibers are, counted against the fraction.
#include "disktune/report_pictures.h"

#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <set>
#include <vector>

#include "disktune/errors.h"
#include "disktune/rve.h"
#include "disktune/sampling.h"
#include "test_util.h"

namespace disktune {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

struct Decoded {
  unsigned width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Decoded decode(const fs::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Decoded d;
  if (!png_image_begin_read_from_file(&image, file.c_str())) {
    ADD_FAILURE() << file << ": " << image.message;
    return d;
  }
  image.format = PNG_FORMAT_RGB;
  d.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, d.rgb.data(), 0, nullptr)) {
    ADD_FAILURE() << file << ": " << image.message;
    return d;
  }
  d.width = image.width;
  d.height = image.height;
  return d;
}

std::size_t distinct_colors(const Decoded& d) {
  std::set<unsigned> colors;
  for (std::size_t i = 0; i + 2 < d.rgb.size(); i += 3) {
    colors.insert(d.rgb[i] << 16 | d.rgb[i + 1] << 8 | d.rgb[i + 2]);
  }
  return colors.size();
}

TEST(ReportPictures, WritesFiveDecodablePictures) {
  const PeriodicBox box(1, 1);
  Rng rng(4);
  const Packing p = sample_mps(box, 0.03, rng);
  const QualityReport q = measure_quality(p, periodic_delaunay(p), 0.03);
  const Spectrum s = measure_spectrum(p);
  TempDir dir;
  write_report_pictures(dir.path.string(), q, &s);
  for (const char* name : {"angles.png", "edges.png", "radial_mean.png", "anisotropy.png"}) {
    const Decoded d = decode(dir.path / name);
    EXPECT_EQ(d.width, 640u) << name;
    EXPECT_EQ(d.height, 400u) << name;
    EXPECT_GE(distinct_colors(d), 3u) << name;  // white, black axes, blue data
  }
  const Decoded image = decode(dir.path / "spectrum.png");
  const unsigned side = static_cast<unsigned>(s.side());
  EXPECT_EQ(image.width, image.height);
  EXPECT_EQ(image.width % side, 0u);
  EXPECT_GE(image.width, 512u);
  EXPECT_GT(distinct_colors(image), 50u);  // a gray ramp, not a flat picture
  // DC at the center, set to 0: black.
  const std::size_t c =
      (image.height / 2 * static_cast<std::size_t>(image.width) + image.width / 2) * 3;
  EXPECT_EQ(image.rgb[c], 0);
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir.path)) files += entry.is_regular_file();
  EXPECT_EQ(files, 5u);  // and no temporaries left
}

TEST(ReportPictures, WithoutASpectrumWritesTheHistogramsOnly) {
  const PeriodicBox box(1, 1);
  Rng rng(5);
  const Packing p = sample_mps(box, 0.05, rng);
  const QualityReport q = measure_quality(p, periodic_delaunay(p), 0.05);
  TempDir dir;
  write_report_pictures(dir.path.string(), q);
  EXPECT_TRUE(fs::exists(dir.path / "angles.png"));
  EXPECT_TRUE(fs::exists(dir.path / "edges.png"));
  EXPECT_FALSE(fs::exists(dir.path / "spectrum.png"));
}

TEST(ReportPictures, FiberPicturesShowTheFibersWhereTheyAre) {
  RveSpec spec;
  spec.width = 1, spec.height = 0.5, spec.diameter = 0.05, spec.gap = 0.0025, spec.fiber_fraction = 0.6;
  const Rve rve = make_rve(spec);
  const FiberStatistics stats = fiber_statistics(rve.cell, rve.centers, rve.diameter);
  const FiberStatistics sample = fiber_statistics(rve.cell, rve.sample_centers, rve.diameter);
  TempDir dir;
  write_fiber_pictures(dir.path.string(), rve.cell, rve.centers, rve.diameters, stats, &sample);
  for (const char* name : {"pair_correlation.png", "ripley_l.png", "nearest.png", "psi6_local.png"}) {
    const Decoded d = decode(dir.path / name);
    EXPECT_EQ(d.width, 640u) << name;
    EXPECT_GE(distinct_colors(d), 3u) << name;
  }
  const Decoded cell = decode(dir.path / "cell.png");
  ASSERT_EQ(cell.width, 800u);
  ASSERT_EQ(cell.height, 400u);  // the cell's aspect
  // Each pixel's center, in the cell (y up), against every fiber and periodic image.
  const double scale = 800;
  std::size_t blue = 0, wrong = 0;
  for (unsigned py = 0; py < cell.height; ++py) {
    for (unsigned px = 0; px < cell.width; ++px) {
      const double x = (px + 0.5) / scale, y = 0.5 - (py + 0.5) / scale;
      double nearest = INFINITY;
      for (const Vec2 c : rve.centers) {
        const double dx = x - c.x - std::round(x - c.x), dy = y - c.y - 0.5 * std::round((y - c.y) / 0.5);
        nearest = std::min(nearest, std::hypot(dx, dy));
      }
      const unsigned char* rgb = &cell.rgb[(static_cast<std::size_t>(py) * cell.width + px) * 3];
      const bool is_blue = rgb[2] > rgb[0] + 50;
      blue += is_blue;
      // A pixel more than one pixel inside or outside a fiber has its color.
      if ((nearest < 0.025 - 1.5 / scale && !is_blue) || (nearest > 0.025 + 1.5 / scale && is_blue)) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_NEAR(double(blue) / (800.0 * 400.0), rve.fiber_fraction, 0.01);
}

TEST(ReportPictures, RefusesAMissingFolder) {
  const PeriodicBox box(1, 1);
  Rng rng(6);
  const Packing p = sample_mps(box, 0.05, rng);
  const QualityReport q = measure_quality(p, periodic_delaunay(p), 0.05);
  TempDir dir;
  const fs::path missing = dir.path / "no" / "such";
  try {
    write_report_pictures(missing.string(), q);
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
  EXPECT_THROW(check_picture_folder(""), IoError);
}

}  // namespace
}  // namespace disktune
