#include "core/device/pdf_device.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <stdexcept>

#include "core/device/atomic_file.hpp"
#include "core/device/page_layout.hpp"

namespace hlr {
namespace {

constexpr double kPointsPerMm = 72.0 / 25.4;

// Drawn in millimetres (the context is scaled once per page) on the layout every device shares, so the
// PDF puts each piece where the JSON device's strokes say it is.
void draw_page(cairo_t* cr, const DrawingPage& page, const PdfOptions& o) {
  const PageLayout layout = fit_to_page(page.frame, page.segments, o.page_spec());
  cairo_save(cr);
  cairo_scale(cr, kPointsPerMm, kPointsPerMm);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_source_rgb(cr, 0, 0, 0);
  if (page.frame) {
    // Top-left corner on the page is the picture's (xmin, ymax): the layout flips y.
    const Point2 corner = layout.to_page_mm({page.frame->xmin, page.frame->ymax});
    cairo_set_line_width(cr, 0.5 * o.line_width_mm);
    cairo_rectangle(cr, corner.x, corner.y, page.frame->width() * layout.scale,
                    page.frame->height() * layout.scale);
    cairo_stroke(cr);
  }
  cairo_set_line_width(cr, o.line_width_mm);
  for (const bool hidden : {false, true}) {
    if (hidden) {
      const double dash[] = {2, 1.2};
      cairo_set_dash(cr, dash, 2, 0);
      cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    }
    for (const VisibleSegment& s : page.segments) {
      if (s.hidden != hidden) continue;
      const Point2 a = layout.to_page_mm(s.s0), b = layout.to_page_mm(s.s1);
      cairo_move_to(cr, a.x, a.y);
      cairo_line_to(cr, b.x, b.y);
    }
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0);
  if (!page.caption.empty()) {
    // In the bottom margin, so a caption never changes where the drawing lands.
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 10 / kPointsPerMm);  // 10 pt
    cairo_move_to(cr, o.margin_mm, o.page_height_mm - o.margin_mm * 0.6);
    cairo_show_text(cr, page.caption.c_str());
  }
  cairo_restore(cr);
}

}  // namespace

void write_pdf(const std::filesystem::path& target, const std::vector<DrawingPage>& pages,
               const PdfOptions& o) {
  check_page_spec(o.page_spec());  // bad paper or margins fail before any file exists
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
    if (surface_status != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(cairo_status_to_string(surface_status));
  });
}

}  // namespace hlr
