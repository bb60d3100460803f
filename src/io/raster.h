// SPDX-License-Identifier: GPL-3.0-or-later
// A small RGB raster for the PNG pictures (internal): pixels, filled rectangles, lines
// and numbers in a built-in 5 x 7 font, so no font or drawing library is needed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace disktune::detail {

struct Rgb {
  std::uint8_t r, g, b;
};

class Raster {
 public:
  Raster(int width, int height, Rgb background);

  int width() const { return w_; }
  int height() const { return h_; }
  /// Rows top to bottom, three bytes a pixel: what PNG_FORMAT_RGB expects.
  const std::vector<std::uint8_t>& bytes() const { return rgb_; }

  /// Pixels outside the raster are ignored, so shapes may cross its border.
  void set(int x, int y, Rgb c);
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);  // inclusive corners, any order
  void line(int x0, int y0, int x1, int y1, Rgb c);       // Bresenham, both ends drawn
  /// Draws `text` (digits, '.', '-', '+', 'e' and space; others as blanks) with its top
  /// left corner at (x, y); each glyph is 6 pixels wide with the gap.
  void text(int x, int y, const std::string& text, Rgb c);
  static int text_width(const std::string& text) { return 6 * static_cast<int>(text.size()) - 1; }

 private:
  int w_, h_;
  std::vector<std::uint8_t> rgb_;
};

/// Writes the raster as a PNG file through write_file_atomically (libpng's simplified
/// API, which reports errors by return value: no longjmp through C++ frames).
void write_png(const std::string& path, const Raster& raster);

}  // namespace disktune::detail
