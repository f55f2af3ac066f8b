#include "core/device/pdf_device.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <stdexcept>

#include "core/device/atomic_file.hpp"

namespace hlr {
namespace {

constexpr double kPointsPerMm = 72.0 / 25.4;

Rect2 page_extent(const DrawingPage& page) {
  if (page.frame) return *page.frame;
  Rect2 r = Rect2::none();
  for (const VisibleSegment& s : page.segments) {
    r.include(s.s0);
    r.include(s.s1);
  }
  return r;
}

void draw_page(cairo_t* cr, const DrawingPage& page, const PdfOptions& o) {
  const double w = o.page_width_mm * kPointsPerMm, h = o.page_height_mm * kPointsPerMm;
  const double margin = o.margin_mm * kPointsPerMm;
  const double caption_space = page.caption.empty() ? 0 : 14;
  const Rect2 ext = page_extent(page);
  if (ext.empty()) return;
  const double ew = std::max(ext.width(), 1e-12), eh = std::max(ext.height(), 1e-12);
  const double scale = std::min((w - 2 * margin) / ew, (h - 2 * margin - caption_space) / eh);
  const double cx = 0.5 * (ext.xmin + ext.xmax), cy = 0.5 * (ext.ymin + ext.ymax);
  // Picture y grows upwards, PDF y downwards.
  auto X = [&](double x) { return 0.5 * w + (x - cx) * scale; };
  auto Y = [&](double y) { return 0.5 * (h - caption_space) - (y - cy) * scale; };

  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_source_rgb(cr, 0, 0, 0);
  if (page.frame) {
    cairo_set_line_width(cr, 0.5 * o.line_width_mm * kPointsPerMm);
    cairo_rectangle(cr, X(page.frame->xmin), Y(page.frame->ymax), page.frame->width() * scale,
                    page.frame->height() * scale);
    cairo_stroke(cr);
  }
  cairo_set_line_width(cr, o.line_width_mm * kPointsPerMm);
  for (const bool hidden : {false, true}) {
    if (hidden) {
      const double dash[] = {2 * kPointsPerMm, 1.2 * kPointsPerMm};
      cairo_set_dash(cr, dash, 2, 0);
      cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    }
    for (const VisibleSegment& s : page.segments) {
      if (s.hidden != hidden) continue;
      cairo_move_to(cr, X(s.s0.x), Y(s.s0.y));
      cairo_line_to(cr, X(s.s1.x), Y(s.s1.y));
    }
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0);
  if (!page.caption.empty()) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 10);
    cairo_move_to(cr, margin, h - margin * 0.6);
    cairo_show_text(cr, page.caption.c_str());
  }
}

}  // namespace

void write_pdf(const std::filesystem::path& target, const std::vector<DrawingPage>& pages, const PdfOptions& o) {
  write_atomically(target, [&](const std::filesystem::path& temp) {
    const double w = o.page_width_mm * kPointsPerMm, h = o.page_height_mm * kPointsPerMm;
    cairo_surface_t* surface = cairo_pdf_surface_create(temp.c_str(), w, h);
    if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
      const std::string why = cairo_status_to_string(cairo_surface_status(surface));
      cairo_surface_destroy(surface);
      throw std::runtime_error(why);
    }
    if (!o.title.empty()) cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, o.title.c_str());
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "hlrscript");
    cairo_t* cr = cairo_create(surface);
    for (const DrawingPage& page : pages) {
      draw_page(cr, page, o);
      cairo_show_page(cr);
    }
    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t surface_status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(cairo_status_to_string(status));
    if (surface_status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(cairo_status_to_string(surface_status));
  });
}

}  // namespace hlr
