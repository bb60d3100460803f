// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/report_pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "disktune/errors.h"
#include "drawing.h"
#include "plot.h"
#include "spectrum_layout.h"

namespace disktune {
namespace {

using detail::Drawing;
using detail::Plot;
using detail::PlotText;
using detail::Rgb;

// Pictures by file stem ("angles"), all drawn before any is written.
using Pictures = std::vector<std::pair<std::string, Drawing>>;

void write_pictures(const std::string& dir, const Pictures& pictures, PictureFormat format) {
  for (const auto& [stem, drawing] : pictures)
    detail::write_picture(dir + "/" + stem + "." + extension(format), drawing, format);
}

constexpr int kWidth = 640, kHeight = 400;
constexpr Rgb kBlue{31, 90, 180};
constexpr Rgb kOrange{230, 120, 20};
constexpr Rgb kGray{150, 150, 150};
constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kWhiteBg{255, 255, 255};
// The spectrum's gray scale: log10 P from -2 (black) to 1 (white). A maximal sample's
// low-frequency gap (P ~ 0.01) is black, its ring (P ~ 2) light, a lattice peak white.
constexpr double kLogLo = -2, kLogHi = 1;

// The powers as gray levels (log10 P from kLogLo, black, to kLogHi, white), framed by
// the normalised frequency along kx and ky, with a gray bar for the scale.
Drawing spectrum_image(const Spectrum& s) {
  const int side = s.side(), K = s.window;
  const detail::SpectrumLayout at = detail::spectrum_layout(s);
  const int extent = side * at.zoom, bar = at.left + extent + 30;
  Drawing r(bar + 90, at.top + extent + 50, kWhiteBg);
  std::vector<Rgb> gray(static_cast<std::size_t>(side) * side);
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      const double p = s.at(col - (K - 1), (K - 1) - row);  // top row is the highest ky
      const double t = p > 0 ? (std::log10(p) - kLogLo) / (kLogHi - kLogLo) : 0;
      const auto g = static_cast<std::uint8_t>(std::lround(255 * std::clamp(t, 0.0, 1.0)));
      gray[static_cast<std::size_t>(row) * side + col] = {g, g, g};
    }
  }
  r.image(at.left, at.top, side, side, at.zoom, at.zoom, std::move(gray));
  // Ticks at round normalised frequencies: (kx, ky) = (k W, k H) / unit for frequency k.
  const double center_x = at.left + (K - 1 + 0.5) * at.zoom, center_y = at.top + (K - 1 + 0.5) * at.zoom;
  const double reach = (K - 1) * s.frequency_unit / std::max(s.width, s.height);
  const double step = reach > 4 ? 2 : reach > 2 ? 1 : 0.5;
  for (double f = -std::floor(reach / step) * step; f <= reach + 1e-9; f += step) {
    const double dx = f * s.width / s.frequency_unit * at.zoom, dy = f * s.height / s.frequency_unit * at.zoom;
    char label[16];
    std::snprintf(label, sizeof label, "%g", std::abs(f) < 1e-12 ? 0.0 : f);
    r.line(center_x + dx, at.top + extent, center_x + dx, at.top + extent + 4, kBlack);
    r.text(center_x + dx, at.top + extent + 16, label, 11, kBlack, Drawing::Align::center);
    r.line(at.left - 4, center_y - dy, at.left, center_y - dy, kBlack);
    r.text(at.left - 7, center_y - dy + 4, label, 11, kBlack, Drawing::Align::right);
  }
  r.text(at.left + extent / 2.0, at.top - 14, "Power spectrum P(k), gray scale of log10 P", 15,
         kBlack, Drawing::Align::center);
  r.text(at.left + extent / 2.0, at.top + extent + 38, "kx (normalised frequency)", 13, kBlack,
         Drawing::Align::center);
  r.text(24, at.top + extent / 2.0, "ky (normalised frequency)", 13, kBlack, Drawing::Align::center,
         true);
  // The scale: a gray ramp from black (log10 P = kLogLo) at the bottom to white at the top.
  std::vector<Rgb> ramp(extent);
  for (int y = 0; y < extent; ++y) {
    const auto g = static_cast<std::uint8_t>(std::lround(255.0 * (extent - 1 - y) / std::max(1, extent - 1)));
    ramp[y] = {g, g, g};
  }
  r.image(bar, at.top, 1, extent, 19, 1, std::move(ramp));
  r.polyline({{bar - 0.5, at.top - 0.5}, {bar + 18.5, at.top - 0.5}, {bar + 18.5, at.top + extent + 0.5},
              {bar - 0.5, at.top + extent + 0.5}, {bar - 0.5, at.top - 0.5}},
             kBlack, 1);
  for (double v = kLogLo; v <= kLogHi + 1e-9; v += 1) {
    const double y = at.top + (kLogHi - v) / (kLogHi - kLogLo) * extent;
    char label[16];
    std::snprintf(label, sizeof label, "%g", v);
    r.line(bar + 18, y, bar + 22, y, kBlack);
    r.text(bar + 25, y + 4, label, 11, kBlack);
  }
  r.text(bar + 75, at.top + extent / 2.0, "log10 P", 13, kBlack, Drawing::Align::center, true);
  return r;
}

/// The y range covers [y_lo, y_hi] and the data, but stops at y_cap, so that a lattice's
/// spikes do not flatten the rest (lines past the cap leave through the frame).
Drawing line_plot(const std::vector<std::array<double, 2>>& points, double reference,
                  const std::string& reference_name, double y_lo, double y_hi, double y_cap,
                  PlotText text) {
  double x_hi = 0;
  for (const auto& p : points) {
    x_hi = std::max(x_hi, p[0]);
    y_lo = std::max(std::min(y_lo, p[1]), -y_cap);
    y_hi = std::min(std::max(y_hi, p[1]), y_cap);
  }
  Plot plot(kWidth, kHeight, 0, x_hi, y_lo, y_hi, std::move(text));
  plot.reference(reference, kGray, reference_name);
  plot.polyline(points, kBlue, "this packing");
  plot.axes();
  return std::move(plot.drawing());
}

/// The histogram's bars over the span of its non-empty bins (overflow not drawn).
Drawing histogram_plot(const Histogram& h, PlotText text) {
  if (h.counts.empty()) {
    Plot empty(kWidth, kHeight, 0, 1, 0, 1, std::move(text));
    empty.axes();
    return std::move(empty.drawing());
  }
  std::size_t first = h.counts.size(), last = 0, top = 1;
  for (std::size_t k = 0; k < h.counts.size(); ++k) {
    if (h.counts[k] == 0) continue;
    first = std::min(first, k);
    last = k;
    top = std::max(top, h.counts[k]);
  }
  if (first > last) first = 0, last = h.counts.size() - 1;  // empty: show the whole range
  const std::size_t pad = std::max<std::size_t>(2, (last - first) / 10);
  first = first > pad ? first - pad : 0;
  last = std::min(last + pad, h.counts.size() - 1);
  Plot plot(kWidth, kHeight, h.lo + first * h.bin_width, h.lo + (last + 1) * h.bin_width, 0,
            1.05 * static_cast<double>(top), std::move(text));
  for (std::size_t k = first; k <= last; ++k) {
    const double x = h.lo + k * h.bin_width;
    plot.bar(x, x + h.bin_width, static_cast<double>(h.counts[k]), kBlue);
  }
  plot.axes();
  return std::move(plot.drawing());
}

constexpr int kCellWidth = 800;

// Disks in a w x h cell, kCellWidth pixels across, rows from the top: a pixel takes disk
// i's color when its center lies in that disk (or, in a periodic cell, one of its
// periodic images), found from the disks whose box covers the pixel's row. One image:
// PDF and SVG embed it, so no seams and small files.
std::vector<Rgb> disk_pixels(double w, double h, const std::vector<Vec2>& centers,
                             const std::vector<double>& radii, const std::vector<Rgb>& colors,
                             bool periodic) {
  const double scale = kCellWidth / w;
  const int height = std::max(1, static_cast<int>(std::lround(h * scale)));
  std::vector<Rgb> pixels(static_cast<std::size_t>(kCellWidth) * height, Rgb{255, 255, 255});
  for (std::size_t i = 0; i < centers.size(); ++i) {
    const Vec2 c = centers[i];
    const double radius = radii[i];
    for (const double dx : {-w, 0.0, w}) {
      for (const double dy : {-h, 0.0, h}) {
        if (!periodic && (dx != 0 || dy != 0)) continue;
        const double cx = c.x + dx, cy = c.y + dy;
        if (cx + radius < 0 || cx - radius > w || cy + radius < 0 || cy - radius > h) continue;
        const int y0 = std::max(0, static_cast<int>(std::floor((h - cy - radius) * scale)));
        const int y1 = std::min(height - 1, static_cast<int>(std::ceil((h - cy + radius) * scale)));
        for (int py = y0; py <= y1; ++py) {
          const double y = h - (py + 0.5) / scale, half = radius * radius - (y - cy) * (y - cy);
          if (half < 0) continue;
          const double reach = std::sqrt(half);
          const int x0 = std::max(0, static_cast<int>(std::ceil((cx - reach) * scale - 0.5)));
          const int x1 = std::min(kCellWidth - 1, static_cast<int>(std::floor((cx + reach) * scale - 0.5)));
          for (int px = x0; px <= x1; ++px)
            pixels[static_cast<std::size_t>(py) * kCellWidth + px] = colors[i];
        }
      }
    }
  }
  return pixels;
}

Drawing disks_image(double w, double h, const std::vector<Vec2>& centers,
                    const std::vector<double>& radii, const std::vector<Rgb>& colors,
                    bool periodic = true) {
  std::vector<Rgb> pixels = disk_pixels(w, h, centers, radii, colors, periodic);
  const int height = static_cast<int>(pixels.size() / kCellWidth);
  Drawing r(kCellWidth, height, {255, 255, 255});
  r.image(0, 0, kCellWidth, height, 1, 1, std::move(pixels));
  return r;
}

// The fibers in blue.
Drawing cell_image(const PeriodicBox& cell, const std::vector<Vec2>& centers,
                   const std::vector<double>& diameters) {
  std::vector<double> radii;
  for (const double d : diameters) radii.push_back(d / 2);
  return disks_image(cell.width(), cell.height(), centers, radii,
                     std::vector<Rgb>(centers.size(), kBlue));
}

// A hue for a lattice orientation in [0, 60) degrees: the color wheel once around.
Rgb orientation_color(double degrees) {
  const double hue = degrees / 60 * 6;  // six sectors
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const auto level = [](double v) { return static_cast<std::uint8_t>(std::lround(40 + 190 * v)); };
  const std::uint8_t hi = level(1), lo = level(0), up = level(f), down = level(1 - f);
  switch (sector) {
    case 0:
      return {hi, up, lo};
    case 1:
      return {down, hi, lo};
    case 2:
      return {lo, hi, up};
    case 3:
      return {lo, down, hi};
    case 4:
      return {up, lo, hi};
    default:
      return {hi, lo, down};
  }
}

// Each disk (drawn at half its radius: the disks of the area fraction, which do not
// overlap) colored by its lattice orientation where it is locally hexagonal, light gray
// where it is not.
Drawing orientation_image(const Packing& packing, const BondOrder& order) {
  std::vector<Vec2> centers;
  std::vector<double> radii;
  std::vector<Rgb> colors;
  const std::vector<DiskId> ids = packing.ids();
  const Frame& frame = packing.frame();
  for (std::size_t i = 0; i < ids.size(); ++i) {
    centers.push_back(frame.wrap(packing.center(ids[i])) - frame.origin);
    radii.push_back(packing.radius(ids[i]) / 2);
    colors.push_back(order.local[i] > kHexagonalPsi6 ? orientation_color(order.orientation[i])
                                                     : Rgb{205, 205, 205});
  }
  // The disks between a title and a legend: the hues over the 60 degrees of a lattice's
  // orientation, and the gray of the disks that are not locally hexagonal.
  std::vector<Rgb> pixels =
      disk_pixels(frame.extent.x, frame.extent.y, centers, radii, colors, frame.periodic);
  constexpr int kTop = 36, kBottom = 56;
  const int height = static_cast<int>(pixels.size() / kCellWidth);
  Drawing r(kCellWidth, kTop + height + kBottom, kWhiteBg);
  r.text(kCellWidth / 2.0, 24, "Disks by lattice orientation, where locally hexagonal", 15, kBlack,
         Drawing::Align::center);
  r.image(0, kTop, kCellWidth, height, 1, 1, std::move(pixels));
  constexpr int kHues = 240;
  std::vector<Rgb> hues(kHues);
  for (int k = 0; k < kHues; ++k) hues[k] = orientation_color(60.0 * k / kHues);
  const int bar_x = 140, bar_y = kTop + height + 14;
  r.image(bar_x, bar_y, kHues, 1, 1, 11, std::move(hues));
  r.text(bar_x - 6, bar_y + 10, "0 deg", 12, kBlack, Drawing::Align::right);
  r.text(bar_x + kHues + 6, bar_y + 10, "60 deg", 12, kBlack);
  r.text(bar_x + kHues / 2.0, bar_y + 30, "lattice orientation (|psi6| > 0.9)", 12, kBlack,
         Drawing::Align::center);
  const int gray_x = 560;
  r.fill_rect(gray_x, bar_y, gray_x + 11, bar_y + 10, {205, 205, 205});
  r.text(gray_x + 18, bar_y + 10, "not locally hexagonal", 12, kBlack);
  return r;
}

Drawing curves_plot(const FiberStatistics& stats, const FiberStatistics* sample, double reference,
                    double (*value)(const FiberStatistics&, std::size_t), PlotText text) {
  const auto curve = [&](const FiberStatistics& s) {
    std::vector<std::array<double, 2>> points;
    for (std::size_t i = 0; i < s.r.size(); ++i) points.push_back({s.r[i], value(s, i)});
    return points;
  };
  const auto fibers = curve(stats);
  double x_hi = 0, y_lo = reference, y_hi = reference;
  for (const auto& p : fibers) x_hi = std::max(x_hi, p[0]), y_lo = std::min(y_lo, p[1]), y_hi = std::max(y_hi, p[1]);
  std::vector<std::array<double, 2>> rsa;
  if (sample) {
    rsa = curve(*sample);
    for (const auto& p : rsa) y_lo = std::min(y_lo, p[1]), y_hi = std::max(y_hi, p[1]);
  }
  Plot plot(kWidth, kHeight, 0, x_hi > 0 ? x_hi : 1, y_lo, y_hi > y_lo ? y_hi : y_lo + 1, std::move(text));
  plot.reference(reference, kGray, "complete spatial randomness");
  if (sample) plot.polyline(rsa, kOrange, "maximal sample it was tuned from");
  plot.polyline(fibers, kBlue, "this arrangement");
  plot.axes();
  return std::move(plot.drawing());
}

}  // namespace

void write_fiber_pictures(const std::string& dir, const PeriodicBox& cell,
                          const std::vector<Vec2>& centers, const std::vector<double>& diameters,
                          const FiberStatistics& stats, const FiberStatistics* sample,
                          PictureFormat format) {
  check_picture_folder(dir);
  if (diameters.size() != centers.size()) {
    throw InvalidInput("fiber pictures: " + std::to_string(centers.size()) + " fibers but " +
                       std::to_string(diameters.size()) + " diameters; give one diameter per fiber");
  }
  Pictures pictures;
  pictures.emplace_back("cell", cell_image(cell, centers, diameters));
  pictures.emplace_back(
      "pair_correlation",
      curves_plot(stats, sample, 1,
                  [](const FiberStatistics& s, std::size_t i) { return s.pair_correlation[i]; },
                  {"Pair correlation g(r)", "r / D (D: mean fiber diameter)", "g(r)"}));
  pictures.emplace_back("ripley_l", curves_plot(stats, sample, 0,
                                                [](const FiberStatistics& s, std::size_t i) {
                                                  return s.ripley_l[i] - s.r[i];
                                                },
                                                {"Ripley's L(r) - r", "r / D", "(L(r) - r) / D"}));
  pictures.emplace_back(
      "nearest", histogram_plot(stats.nearest_histogram[0],
                                {"Nearest neighbour distance", "center distance / D", "fibers"}));
  pictures.emplace_back(
      "psi6_local",
      histogram_plot(stats.psi6_local, {"Local bond order |psi6| (1: hexagonal)",
                                        "|psi6| of a fiber's 6 nearest bonds", "fibers"}));
  write_pictures(dir, pictures, format);
}

std::string extension(PictureFormat format) {
  return format == PictureFormat::pdf ? "pdf" : format == PictureFormat::svg ? "svg" : "png";
}

void check_picture_folder(const std::string& dir) {
  std::error_code ec;
  if (dir.empty() || !std::filesystem::is_directory(dir, ec)) {
    throw IoError("the picture folder '" + dir + "' does not exist: create it first (mkdir -p " +
                  dir + ") or name another folder");
  }
}

namespace {

// A color from red (t = 0) through yellow to green (t = 1), scaled by `light`.
Rgb red_to_green(double t, double light) {
  t = std::clamp(t, 0.0, 1.0);
  const double r = t < 0.5 ? 1.0 : 2 * (1 - t), g = t < 0.5 ? 2 * t : 1.0, b = 0.15;
  const auto level = [&](double v) {
    return static_cast<std::uint8_t>(std::lround(255 * v * light));
  };
  return {level(r * 0.9 + 0.05), level(g * 0.8 + 0.1), level(b)};
}

// The surface mesh seen from the direction (1, 1, 1) (y up on the picture), drawn far
// triangles first, each shaded by how squarely it faces that way and colored by its
// smallest angle: 30 degrees (the bound a one-radius maximal packing guarantees) and
// below red, through yellow at 45, to green at 60 (equilateral).
Drawing surface_image(const SurfaceMesh& mesh) {
  constexpr int kWidth = 800, kTop = 40, kBottom = 50, kMargin = 20;
  const double s3 = 1 / std::sqrt(3.0), s2 = 1 / std::sqrt(2.0), s6 = 1 / std::sqrt(6.0);
  const Vec3 toward{s3, s3, s3}, right{s2, 0, -s2}, up{-s6, 2 * s6, -s6};
  std::vector<std::array<double, 2>> at(mesh.vertices.size());
  double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
  for (std::size_t i = 0; i < at.size(); ++i) {
    at[i] = {dot(mesh.vertices[i], right), dot(mesh.vertices[i], up)};
    lo_x = std::min(lo_x, at[i][0]), hi_x = std::max(hi_x, at[i][0]);
    lo_y = std::min(lo_y, at[i][1]), hi_y = std::max(hi_y, at[i][1]);
  }
  const double span_x = std::max(hi_x - lo_x, 1e-300), span_y = std::max(hi_y - lo_y, 1e-300);
  const double scale =
      std::min((kWidth - 2.0 * kMargin) / span_x, (kWidth - 2.0 * kMargin) / span_y);
  const int height = kTop + kBottom + 2 * kMargin + static_cast<int>(std::ceil(span_y * scale));
  Drawing r(kWidth, height, kWhiteBg);
  const double x0 = (kWidth - span_x * scale) / 2;
  const auto pixel = [&](std::uint32_t v) {
    return std::array<double, 2>{x0 + (at[v][0] - lo_x) * scale,
                                 kTop + kMargin + (hi_y - at[v][1]) * scale};
  };
  const std::vector<double> smallest = smallest_angles(mesh);
  std::vector<std::pair<double, std::size_t>> order;  // depth toward the viewer, triangle
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    order.push_back(
        {dot(mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]], toward), t});
  }
  std::sort(order.begin(), order.end());
  for (const auto& [depth, t] : order) {
    const auto& tri = mesh.triangles[t];
    const Vec3 n = cross(mesh.vertices[tri[1]] - mesh.vertices[tri[0]],
                         mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    const double facing = norm(n) > 0 ? std::fabs(dot(n, toward)) / norm(n) : 0;
    r.fill_polygon({pixel(tri[0]), pixel(tri[1]), pixel(tri[2])},
                   red_to_green((smallest[t] - 30) / 30, 0.35 + 0.65 * facing));
  }
  r.text(kWidth / 2.0, 26, "Triangles by their smallest angle", 15, kBlack, Drawing::Align::center);
  // The color bar: 30 to 60 degrees.
  const int bar_y = height - 38, bar_x = kWidth / 2 - 150;
  std::vector<Rgb> bar(300);
  for (int k = 0; k < 300; ++k) bar[k] = red_to_green(k / 299.0, 1);
  r.image(bar_x, bar_y, 300, 1, 1, 11, std::move(bar));
  r.text(bar_x - 8, bar_y + 10, "30 deg or less", 12, kBlack, Drawing::Align::right);
  r.text(bar_x + 308, bar_y + 10, "60 deg", 12, kBlack);
  r.text(kWidth / 2.0, bar_y + 28, "smallest angle of the triangle", 12, kBlack,
         Drawing::Align::center);
  return r;
}

// angles.png and edges.png of a mesh: `triangles` names them in the titles, `length` is
// the edge-length axis.
void add_mesh_histograms(Pictures& pictures, const QualityReport::Angles& angles,
                         const QualityReport::Edges& edges, const std::string& triangles,
                         const std::string& length) {
  pictures.emplace_back("angles", histogram_plot(angles.histogram, {"Angles of the " + triangles,
                                                                    "angle (degrees)", "angles"}));
  pictures.emplace_back(
      "edges",
      histogram_plot(edges.histogram, {"Edge lengths of the " + triangles, length, "edges"}));
}

}  // namespace

void write_report_pictures(const std::string& dir, const SurfaceMeshQuality& quality,
                           const SurfaceMesh& mesh, PictureFormat format) {
  check_picture_folder(dir);
  Pictures pictures;
  pictures.emplace_back("surface", surface_image(mesh));
  add_mesh_histograms(pictures, quality.angles, quality.edges, "restricted Delaunay triangles",
                      "length / r (the mean radius of its ends)");
  write_pictures(dir, pictures, format);
}

void write_report_pictures(const std::string& dir, const PlanarQualityReport& report,
                           const Packing& packing, PictureFormat format) {
  check_picture_folder(dir);
  Pictures pictures;
  if (report.order.count == packing.size())
    pictures.emplace_back("orientation", orientation_image(packing, report.order));
  add_mesh_histograms(pictures, report.all.angles, report.all.edges,
                      "constrained Delaunay triangles", "length / r (the mean radius of its ends)");
  write_pictures(dir, pictures, format);
}

void write_report_pictures(const std::string& dir, const QualityReport& report,
                           const Spectrum* spectrum, const Packing* packing, PictureFormat format) {
  check_picture_folder(dir);
  Pictures pictures;
  if (packing && report.order.count == packing->size())
    pictures.emplace_back("orientation", orientation_image(*packing, report.order));
  add_mesh_histograms(pictures, report.angles, report.edges, "Delaunay triangles", "length / r");
  if (spectrum) {
    pictures.emplace_back("spectrum", spectrum_image(*spectrum));
    pictures.emplace_back(
        "radial_mean",
        line_plot(spectrum->radial_mean, 1, "white noise (P = 1)", 0, 2, 4,
                  {"Radial mean of the power spectrum", "normalised frequency", "mean power P"}));
    pictures.emplace_back("anisotropy",
                          line_plot(spectrum->anisotropy_db, 0, "0 dB", -10, 10, 30,
                                    {"Anisotropy of the power spectrum", "normalised frequency",
                                     "10 log10(variance / mean^2) (dB)"}));
  }
  write_pictures(dir, pictures, format);
}

}  // namespace disktune
