// SPDX-License-Identifier: GPL-3.0-or-later
#include "drawing.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <utility>

#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune::detail {
namespace {

void set_color(cairo_t* cr, Rgb c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

void select_font(cairo_t* cr) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Drawing::Drawing(int width, int height, Rgb background) : w_(width), h_(height) {
  if (width <= 0 || height <= 0 || width > 100000 || height > 100000) {
    throw IoError("cannot make a " + std::to_string(width) + " x " + std::to_string(height) +
                  " picture");
  }
  measure_surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
  measure_ = cairo_create(measure_surface_);
  if (cairo_status(measure_) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_status(measure_));
    cairo_destroy(measure_);
    cairo_surface_destroy(measure_surface_);
    throw IoError("cannot make a picture: cairo says: " + why);
  }
  select_font(measure_);
  fill_rect(0, 0, width - 1, height - 1, background);
}

Drawing::~Drawing() {
  if (measure_) cairo_destroy(measure_);
  if (measure_surface_) cairo_surface_destroy(measure_surface_);
}

Drawing::Drawing(Drawing&& other) noexcept
    : w_(other.w_),
      h_(other.h_),
      steps_(std::move(other.steps_)),
      measure_surface_(std::exchange(other.measure_surface_, nullptr)),
      measure_(std::exchange(other.measure_, nullptr)) {}

Drawing& Drawing::operator=(Drawing&& other) noexcept {
  std::swap(w_, other.w_), std::swap(h_, other.h_), std::swap(steps_, other.steps_);
  std::swap(measure_surface_, other.measure_surface_), std::swap(measure_, other.measure_);
  return *this;
}

void Drawing::play(cairo_t* cr) const {
  select_font(cr);
  for (const auto& step : steps_) step(cr);
}

void Drawing::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  steps_.push_back([=](cairo_t* cr) {
    // Whole pixels: a rectangle on pixel edges covers each pixel fully or not at all.
    cairo_rectangle(cr, x0, y0, x1 - x0 + 1, y1 - y0 + 1);
    set_color(cr, c);
    cairo_fill(cr);
  });
}

void Drawing::image(double x, double y, int cols, int rows, double cell_w, double cell_h,
                    std::vector<Rgb> pixels) {
  if (cols <= 0 || rows <= 0 || pixels.size() != static_cast<std::size_t>(cols) * rows) return;
  steps_.push_back([=, pixels = std::move(pixels)](cairo_t* cr) {
    cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, cols, rows);
    cairo_surface_flush(image);
    unsigned char* data = cairo_image_surface_get_data(image);
    if (!data) {  // out of memory: cairo made an error surface; the picture's status says so
      cairo_surface_destroy(image);
      return;
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
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_scale(cr, cell_w, cell_h);
    cairo_set_source_surface(cr, image, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);  // blocks, not a blur
    cairo_rectangle(cr, 0, 0, cols, rows);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(image);
  });
}

void Drawing::line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) {
  polyline({{x0, y0}, {x1, y1}}, c, width, dashed);
}

void Drawing::polyline(const std::vector<std::array<double, 2>>& points, Rgb c, double width,
                       bool dashed) {
  if (points.size() < 2) return;
  steps_.push_back([=](cairo_t* cr) {
    cairo_move_to(cr, points[0][0], points[0][1]);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr, points[i][0], points[i][1]);
    const double dash[] = {4, 3};
    cairo_set_dash(cr, dash, dashed ? 2 : 0, 0);
    cairo_set_line_width(cr, width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    set_color(cr, c);
    cairo_stroke(cr);
    cairo_set_dash(cr, dash, 0, 0);
  });
}

void Drawing::fill_polygon(const std::vector<std::array<double, 2>>& points, Rgb c) {
  if (points.size() < 3) return;
  steps_.push_back([=](cairo_t* cr) {
    cairo_move_to(cr, points[0][0], points[0][1]);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr, points[i][0], points[i][1]);
    cairo_close_path(cr);
    set_color(cr, c);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.5);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
  });
}

void Drawing::clip(double x0, double y0, double x1, double y1) {
  steps_.push_back([=](cairo_t* cr) {
    cairo_reset_clip(cr);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    cairo_clip(cr);
  });
}

void Drawing::unclip() {
  steps_.push_back([](cairo_t* cr) { cairo_reset_clip(cr); });
}

double Drawing::text_width(const std::string& text, double size) const {
  cairo_set_font_size(measure_, size);
  cairo_text_extents_t e;
  cairo_text_extents(measure_, text.c_str(), &e);
  return e.x_advance;
}

void Drawing::text(double x, double y, const std::string& text, double size, Rgb c, Align align,
                   bool upward) {
  const double shift = align == Align::left     ? 0
                       : align == Align::center ? text_width(text, size) / 2
                                                : text_width(text, size);
  steps_.push_back([=](cairo_t* cr) {
    cairo_save(cr);
    cairo_translate(cr, x, y);
    if (upward) cairo_rotate(cr, -1.5707963267948966);
    cairo_move_to(cr, -shift, 0);
    cairo_set_font_size(cr, size);
    set_color(cr, c);
    cairo_show_text(cr, text.c_str());
    cairo_restore(cr);
  });
}

void write_picture(const std::string& path, const Drawing& drawing, PictureFormat format) {
  std::string encoded;
  const int w = drawing.width(), h = drawing.height();
  cairo_surface_t* target =
      format == PictureFormat::pdf   ? cairo_pdf_surface_create_for_stream(append, &encoded, w, h)
      : format == PictureFormat::svg ? cairo_svg_surface_create_for_stream(append, &encoded, w, h)
                                     : cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(target);
  drawing.play(cr);
  cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  if (status == CAIRO_STATUS_SUCCESS) {
    if (format == PictureFormat::png) {
      cairo_surface_flush(target);
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
