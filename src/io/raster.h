// SPDX-License-Identifier: GPL-3.0-or-later
// A picture for the PNG files (internal), drawn with cairo: pixel-exact filled
// rectangles (the cell and spectrum pictures are judged pixel by pixel), antialiased
// lines and text in the system's sans-serif font (axis titles, legends).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

typedef struct _cairo_surface cairo_surface_t;
typedef struct _cairo cairo_t;

namespace disktune::detail {

struct Rgb {
  std::uint8_t r, g, b;
};

class Raster {
 public:
  Raster(int width, int height, Rgb background);
  ~Raster();
  Raster(Raster&& other) noexcept;
  Raster& operator=(Raster&& other) noexcept;
  Raster(const Raster&) = delete;
  Raster& operator=(const Raster&) = delete;

  int width() const { return w_; }
  int height() const { return h_; }

  /// Every pixel from (x0, y0) to (x1, y1), corners included, in any order; exactly
  /// these pixels, in exactly this color. Outside the picture: ignored.
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
  /// An antialiased line (pixel centers at .5), `width` pixels wide, dashed if asked.
  void line(double x0, double y0, double x1, double y1, Rgb c, double width = 1, bool dashed = false);
  /// A filled polygon through points given in pixels, its outline drawn in the same
  /// color half a pixel wide so that polygons sharing an edge leave no seam.
  void fill_polygon(const std::vector<std::array<double, 2>>& points, Rgb c);
  /// Line segments through points given in pixels.
  void polyline(const std::vector<std::array<double, 2>>& points, Rgb c, double width = 1.5, bool dashed = false);
  /// Drawing limited to a rectangle until unclip().
  void clip(double x0, double y0, double x1, double y1);
  void unclip();

  enum class Align { left, center, right };
  /// `text` `size` pixels high with its baseline at y and x its left end, middle or right
  /// end; with `upward` turned a quarter to read from bottom to top (x, y then the
  /// baseline's anchor after the turn).
  void text(double x, double y, const std::string& text, double size, Rgb c, Align align = Align::left,
            bool upward = false);
  double text_width(const std::string& text, double size) const;

  cairo_surface_t* surface() const { return surface_; }

 private:
  int w_, h_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

/// Writes the picture as an RGB PNG file through write_file_atomically.
void write_png(const std::string& path, const Raster& raster);

}  // namespace disktune::detail
