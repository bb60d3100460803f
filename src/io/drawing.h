// SPDX-License-Identifier: GPL-3.0-or-later
// A picture for the report's files (internal): its drawing steps are kept and played
// with cairo onto the file's own surface, a PNG image, a PDF page or an SVG: pixel-exact
// filled rectangles in the PNG (the cell and spectrum pictures are judged pixel by
// pixel), antialiased lines and text in the system's sans-serif font (axis titles,
// legends), vectors and real text in PDF and SVG. (Not a cairo recording surface:
// replayed into PDF or SVG, cairo 1.16 keeps some of its surfaces alive for good.)
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "disktune/report_pictures.h"

typedef struct _cairo_surface cairo_surface_t;
typedef struct _cairo cairo_t;

namespace disktune::detail {

struct Rgb {
  std::uint8_t r, g, b;
};

class Drawing {
 public:
  Drawing(int width, int height, Rgb background);
  ~Drawing();
  Drawing(Drawing&& other) noexcept;
  Drawing& operator=(Drawing&& other) noexcept;
  Drawing(const Drawing&) = delete;
  Drawing& operator=(const Drawing&) = delete;

  int width() const { return w_; }
  int height() const { return h_; }

  /// Every pixel from (x0, y0) to (x1, y1), corners included, in any order; exactly
  /// these pixels, in exactly this color. Outside the picture: ignored.
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
  /// An image of cols x rows cells (pixels[row * cols + col], rows from the top), each
  /// cell_w x cell_h units, its top left corner at (x, y): exact pixels in the PNG at
  /// whole positions and sizes, one embedded image (no seams) in PDF and SVG.
  void image(double x, double y, int cols, int rows, double cell_w, double cell_h,
             std::vector<Rgb> pixels);
  /// An antialiased line (pixel centers at .5), `width` pixels wide, dashed if asked.
  void line(double x0, double y0, double x1, double y1, Rgb c, double width = 1,
            bool dashed = false);
  /// A filled polygon through points given in pixels, its outline drawn in the same
  /// color half a pixel wide so that polygons sharing an edge leave no seam.
  void fill_polygon(const std::vector<std::array<double, 2>>& points, Rgb c);
  /// Line segments through points given in pixels.
  void polyline(const std::vector<std::array<double, 2>>& points, Rgb c, double width = 1.5,
                bool dashed = false);
  /// Drawing limited to a rectangle until unclip().
  void clip(double x0, double y0, double x1, double y1);
  void unclip();

  enum class Align { left, center, right };
  /// `text` `size` pixels high with its baseline at y and x its left end, middle or right
  /// end; with `upward` turned a quarter to read from bottom to top (x, y then the
  /// baseline's anchor after the turn).
  void text(double x, double y, const std::string& text, double size, Rgb c,
            Align align = Align::left, bool upward = false);
  double text_width(const std::string& text, double size) const;

  /// Plays every step onto `cr` (a context whose surface is width() x height()).
  void play(cairo_t* cr) const;

 private:
  int w_, h_;
  std::vector<std::function<void(cairo_t*)>> steps_;
  cairo_surface_t* measure_surface_ = nullptr;  // for text_width: a 1 x 1 image
  cairo_t* measure_ = nullptr;
};

/// Writes the picture as an RGB PNG (one pixel a unit), a PDF or an SVG (one point a
/// unit) through write_file_atomically; IoError when cairo or the file fails.
void write_picture(const std::string& path, const Drawing& drawing, PictureFormat format);

}  // namespace disktune::detail
