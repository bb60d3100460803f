// SPDX-License-Identifier: GPL-3.0-or-later
// The report's PNG pictures: decoded here with libpng, of the expected size, not blank,
// with words (title and axis titles) where they belong; the spectrum's gray levels are
// the powers, block by block; a missing folder is refused before anything is written.
// The fiber cell's picture: its blue pixels are where the fibers are, counted against
// the fraction. PDF and SVG: read here as text (the PDF's streams inflated with zlib),
// pages the PNG's size, text drawn as text from an embedded font, the spectrum one image.
#include "disktune/report_pictures.h"

#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "../src/io/spectrum_layout.h"
#include "disktune/errors.h"
#include "disktune/rve.h"
#include "disktune/sampling.h"
#include "disktune/surface_mesh.h"
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

// Dark pixels (text, lines) in the rectangle [x0, x1) x [y0, y1).
std::size_t dark_pixels(const Decoded& d, unsigned x0, unsigned y0, unsigned x1, unsigned y1) {
  std::size_t n = 0;
  for (unsigned y = y0; y < std::min(y1, d.height); ++y)
    for (unsigned x = x0; x < std::min(x1, d.width); ++x) n += d.rgb[(static_cast<std::size_t>(y) * d.width + x) * 3] < 100;
  return n;
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
    // A title above the frame, an axis title below the numbers, one left of them.
    EXPECT_GT(dark_pixels(d, 100, 0, 600, 26), 40u) << name << ": title";
    EXPECT_GT(dark_pixels(d, 100, 385, 600, 400), 40u) << name << ": x axis title";
    EXPECT_GT(dark_pixels(d, 0, 50, 26, 350), 40u) << name << ": y axis title";
  }
  const Decoded image = decode(dir.path / "spectrum.png");
  const detail::SpectrumLayout at = detail::spectrum_layout(s);
  const int K = s.window, side = s.side(), extent = side * at.zoom;
  EXPECT_GE(extent, 512);
  ASSERT_GE(image.width, static_cast<unsigned>(at.left + extent));
  ASSERT_GE(image.height, static_cast<unsigned>(at.top + extent));
  // Every frequency's block, at its middle pixel: the gray of its power, log10 P from -2
  // (black) to 1 (white), ky growing upward; DC (set to 0) black.
  std::size_t wrong = 0;
  for (int ky = 1 - K; ky < K; ++ky) {
    for (int kx = 1 - K; kx < K; ++kx) {
      const double p = s.at(kx, ky);
      const double t = p > 0 ? std::clamp((std::log10(p) + 2) / 3, 0.0, 1.0) : 0;
      const std::size_t x = at.left + (kx + K - 1) * at.zoom + at.zoom / 2, y = at.top + (K - 1 - ky) * at.zoom + at.zoom / 2;
      wrong += std::abs(image.rgb[(y * image.width + x) * 3] - std::lround(255 * t)) > 1;
    }
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(distinct_colors(image), 50u);  // a gray ramp, not a flat picture
  EXPECT_GT(dark_pixels(image, at.left, 0, at.left + extent, at.top - 4), 40u) << "title";
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
    EXPECT_GT(dark_pixels(d, 100, 0, 600, 26), 40u) << name << ": title";
    EXPECT_GT(dark_pixels(d, 0, 50, 26, 350), 40u) << name << ": y axis title";
  }
  // The curves' legend names the arrangement (blue), the sample (orange) and the
  // reference (gray): three line samples of those colors at its left end.
  const Decoded g = decode(dir.path / "pair_correlation.png");
  std::size_t orange = 0;
  for (std::size_t i = 0; i + 2 < g.rgb.size(); i += 3) orange += g.rgb[i] > 200 && g.rgb[i + 1] > 90 && g.rgb[i + 1] < 150 && g.rgb[i + 2] < 60;
  EXPECT_GT(orange, 20u);
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

// The surface picture: an octahedron's equilateral triangles are green, a thin
// triangle's red; the histograms are there too.
TEST(ReportPictures, TheSurfaceIsColoredByEachTrianglesSmallestAngle) {
  SurfaceMesh octahedron;
  octahedron.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                          {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  // Red or green pixels above the color bar (the picture's last 60 rows).
  const auto count = [](const Decoded& d, bool want_red) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < std::size_t{d.width} * (d.height - 60) * 3; i += 3) {
      const int r = d.rgb[i], g = d.rgb[i + 1];
      n += want_red ? r > g + 60 : g > r + 60;
    }
    return n;
  };
  TempDir dir;
  write_report_pictures(dir.path.string(),
                        measure_surface_mesh(octahedron, std::vector<double>(6, 1.0)), octahedron);
  const Decoded d = decode(dir.path / "surface.png");
  EXPECT_EQ(d.width, 800u);
  EXPECT_GT(count(d, false), 100000u);  // the octahedron fills much of the picture, green
  EXPECT_EQ(count(d, true), 0u);
  EXPECT_GT(dark_pixels(d, 200, 0, 600, 40), 40u) << "title";
  for (const char* name : {"angles.png", "edges.png"})
    EXPECT_GE(distinct_colors(decode(dir.path / name)), 3u) << name;

  SurfaceMesh sliver;  // smallest angle about 11 degrees
  sliver.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.1, 0}};
  sliver.triangles = {{0, 1, 2}};
  TempDir thin;
  write_report_pictures(thin.path.string(),
                        measure_surface_mesh(sliver, std::vector<double>(3, 1.0)), sliver);
  EXPECT_GT(count(decode(thin.path / "surface.png"), true), 10000u);
  EXPECT_EQ(count(decode(thin.path / "surface.png"), false), 0u);
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every stream of a PDF, inflated where it is Flate-compressed (as cairo writes them).
std::string pdf_streams(const std::string& pdf) {
  std::string out;
  for (std::size_t at = pdf.find("stream\n"); at != std::string::npos;
       at = pdf.find("stream\n", at + 1)) {
    if (at >= 3 && pdf.compare(at - 3, 3, "end") == 0) continue;
    const std::size_t begin = at + 7, end = pdf.find("endstream", begin);
    if (end == std::string::npos) break;
    z_stream z{};
    if (inflateInit(&z) != Z_OK) continue;
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(pdf.data() + begin));
    z.avail_in = static_cast<uInt>(end - begin);
    char buffer[1 << 14];
    int status = Z_OK;
    while (status == Z_OK) {
      z.next_out = reinterpret_cast<Bytef*>(buffer);
      z.avail_out = sizeof buffer;
      status = inflate(&z, Z_NO_FLUSH);
      out.append(buffer, sizeof buffer - z.avail_out);
    }
    inflateEnd(&z);
    out += '\n';
  }
  return out;
}

std::size_t occurrences(const std::string& text, const std::regex& what) {
  return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), what), std::sregex_iterator()));
}

TEST(ReportPictures, PdfAndSvgPicturesAreVectorsWithRealTextOnThePngsPage) {
  const PeriodicBox box(1, 1);
  Rng rng(4);
  const Packing p = sample_mps(box, 0.03, rng);
  const QualityReport q = measure_quality(p, periodic_delaunay(p), 0.03);
  const Spectrum s = measure_spectrum(p);
  TempDir dir;  // one folder per format in it
  const fs::path png = dir.path / "png", pdf = dir.path / "pdf", svg = dir.path / "svg";
  for (const fs::path& folder : {png, pdf, svg}) fs::create_directory(folder);
  write_report_pictures(png.string(), q, &s, &p);
  write_report_pictures(pdf.string(), q, &s, &p, PictureFormat::pdf);
  write_report_pictures(svg.string(), q, &s, &p, PictureFormat::svg);
  const std::vector<std::string> stems{"orientation", "angles",      "edges",
                                       "spectrum",    "radial_mean", "anisotropy"};
  for (const fs::path& folder : {png, pdf, svg}) {
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(folder)) files += entry.is_regular_file();
    EXPECT_EQ(files, stems.size());  // these and nothing else
  }
  for (const std::string& stem : stems) {
    const Decoded page = decode(png / (stem + ".png"));
    const std::string size = std::to_string(page.width) + " " + std::to_string(page.height);
    const std::string a = slurp(pdf / (stem + ".pdf"));
    ASSERT_FALSE(a.empty()) << stem;
    EXPECT_EQ(a.rfind("%PDF-", 0), 0u) << stem;
    EXPECT_NE(a.find("%%EOF", a.size() - 8), std::string::npos) << stem << ": not finished";
    EXPECT_EQ(occurrences(a, std::regex("/Type /Page\\b(?!s)")), 1u) << stem;
    EXPECT_NE(a.find("/MediaBox [ 0 0 " + size + " ]"), std::string::npos) << stem;
    const std::string b = slurp(svg / (stem + ".svg"));
    EXPECT_EQ(b.rfind("<?xml", 0), 0u) << stem;
    EXPECT_NE(b.find("viewBox=\"0 0 " + size + "\""), std::string::npos) << stem;
    EXPECT_NE(b.find("</svg>"), std::string::npos) << stem << ": not finished";
    EXPECT_NE(a.find("/FontFile"), std::string::npos) << stem << ": no embedded font";
    // Text shown with the text operators (a title and axis titles at least), not paths.
    EXPECT_GE(occurrences(pdf_streams(a), std::regex("\\bT[Jj]\\b")), 3u) << stem;
    EXPECT_GE(occurrences(b, std::regex("<use xlink:href=\"#glyph")), 20u) << stem << ": no text";
  }
  // The spectrum's gray blocks: one image of its frequencies, not thousands of squares.
  const std::string side = std::to_string(s.side());
  const std::string a = slurp(pdf / "spectrum.pdf");
  EXPECT_NE(a.find("/Width " + side), std::string::npos);
  EXPECT_NE(a.find("/Height " + side), std::string::npos);
  EXPECT_NE(slurp(svg / "spectrum.svg").find("<image id=\"image"), std::string::npos);
  EXPECT_EQ(extension(PictureFormat::pdf), "pdf");
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
