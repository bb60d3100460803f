// SPDX-License-Identifier: GPL-3.0-or-later
#include "drawing.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <sstream>
#include <utility>

#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune::detail {
namespace {

void set_color(cairo_t* cr, Rgb c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Drawing::Drawing(int width, int height, Rgb background) : w_(width), h_(height) {
  // Recorded, so that one drawing can be replayed as pixels or as vectors.
  const cairo_rectangle_t extents{0, 0, static_cast<double>(width), static_cast<double>(height)};
  surface_ = cairo_recording_surface_create(CAIRO_CONTENT_COLOR, &extents);
  cr_ = cairo_create(surface_);
  if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_status(cr_));
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
    throw IoError("cannot make a " + std::to_string(width) + " x " + std::to_string(height) +
                  " picture: " + why);
  }
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  fill_rect(0, 0, width - 1, height - 1, background);
}

Drawing::~Drawing() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

Drawing::Drawing(Drawing&& other) noexcept
    : w_(other.w_),
      h_(other.h_),
      surface_(std::exchange(other.surface_, nullptr)),
      cr_(std::exchange(other.cr_, nullptr)) {}

Drawing& Drawing::operator=(Drawing&& other) noexcept {
  std::swap(w_, other.w_), std::swap(h_, other.h_);
  std::swap(surface_, other.surface_), std::swap(cr_, other.cr_);
  return *this;
}

void Drawing::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  // Whole pixels: a rectangle on pixel edges covers each pixel fully or not at all.
  cairo_rectangle(cr_, x0, y0, x1 - x0 + 1, y1 - y0 + 1);
  set_color(cr_, c);
  cairo_fill(cr_);
}

void Drawing::image(double x, double y, int cols, int rows, double cell_w, double cell_h,
                    const std::vector<Rgb>& pixels) {
  if (cols <= 0 || rows <= 0 || pixels.size() != static_cast<std::size_t>(cols) * rows) return;
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, cols, rows);
  cairo_surface_flush(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  if (!data) {
    cairo_surface_destroy(image);
    throw IoError("cannot make a " + std::to_string(cols) + " x " + std::to_string(rows) +
                  " image for a picture");
  }
  const int stride = cairo_image_surface_get_stride(image);
  for (int row = 0; row < rows; ++row) {
    auto* line = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(row) * stride);
    for (int col = 0; col < cols; ++col) {
      const Rgb c = pixels[static_cast<std::size_t>(row) * cols + col];
      line[col] = std::uint32_t{c.r} << 16 | std::uint32_t{c.g} << 8 | c.b;
    }
  }
  cairo_surface_mark_dirty(image);
  cairo_save(cr_);
  cairo_translate(cr_, x, y);
  cairo_scale(cr_, cell_w, cell_h);
  cairo_set_source_surface(cr_, image, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr_), CAIRO_FILTER_NEAREST);  // blocks, not a blur
  cairo_rectangle(cr_, 0, 0, cols, rows);
  cairo_fill(cr_);
  cairo_restore(cr_);
  cairo_surface_destroy(image);  // the recording holds its own reference
}

void Drawing::line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) {
  polyline({{x0, y0}, {x1, y1}}, c, width, dashed);
}

void Drawing::polyline(const std::vector<std::array<double, 2>>& points, Rgb c, double width,
                       bool dashed) {
  if (points.size() < 2) return;
  cairo_move_to(cr_, points[0][0], points[0][1]);
  for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, points[i][0], points[i][1]);
  const double dash[] = {4, 3};
  cairo_set_dash(cr_, dash, dashed ? 2 : 0, 0);
  cairo_set_line_width(cr_, width);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  set_color(cr_, c);
  cairo_stroke(cr_);
  cairo_set_dash(cr_, dash, 0, 0);
}

void Drawing::fill_polygon(const std::vector<std::array<double, 2>>& points, Rgb c) {
  if (points.size() < 3) return;
  cairo_move_to(cr_, points[0][0], points[0][1]);
  for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, points[i][0], points[i][1]);
  cairo_close_path(cr_);
  set_color(cr_, c);
  cairo_fill_preserve(cr_);
  cairo_set_line_width(cr_, 0.5);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr_);
}

void Drawing::clip(double x0, double y0, double x1, double y1) {
  cairo_reset_clip(cr_);
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  cairo_clip(cr_);
}

void Drawing::unclip() { cairo_reset_clip(cr_); }

double Drawing::text_width(const std::string& text, double size) const {
  cairo_set_font_size(cr_, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr_, text.c_str(), &e);
  return e.x_advance;
}

void Drawing::text(double x, double y, const std::string& text, double size, Rgb c, Align align,
                   bool upward) {
  const double shift = align == Align::left     ? 0
                       : align == Align::center ? text_width(text, size) / 2
                                                : text_width(text, size);
  cairo_save(cr_);
  cairo_translate(cr_, x, y);
  if (upward) cairo_rotate(cr_, -1.5707963267948966);
  cairo_move_to(cr_, -shift, 0);
  cairo_set_font_size(cr_, size);
  set_color(cr_, c);
  cairo_show_text(cr_, text.c_str());
  cairo_restore(cr_);
}

void write_picture(const std::string& path, const Drawing& drawing, PictureFormat format) {
  std::string encoded;
  const int w = drawing.width(), h = drawing.height();
  cairo_surface_t* target =
      format == PictureFormat::pdf   ? cairo_pdf_surface_create_for_stream(append, &encoded, w, h)
      : format == PictureFormat::svg ? cairo_svg_surface_create_for_stream(append, &encoded, w, h)
                                     : cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_surface_flush(drawing.surface());
  cairo_t* cr = cairo_create(target);
  cairo_set_source_surface(cr, drawing.surface(), 0, 0);
  cairo_paint(cr);
  cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  if (status == CAIRO_STATUS_SUCCESS) {
    if (format == PictureFormat::png) {
      status = cairo_surface_write_to_png_stream(target, append, &encoded);
    } else {
      cairo_surface_finish(target);  // the PDF or SVG is streamed out only now
      status = cairo_surface_status(target);
    }
  }
  cairo_surface_destroy(target);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw IoError("cannot encode the picture " + path +
                  ": cairo says: " + cairo_status_to_string(status));
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(encoded.data(), static_cast<std::streamsize>(encoded.size()));
  });
}

}  // namespace disktune::detail
