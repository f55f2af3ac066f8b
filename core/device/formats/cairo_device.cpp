#include "core/device/formats/cairo_device.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/device/formats/cairo_handles.hpp"
#include "core/device/formats/pdf_writer.hpp"
#include "core/device/formats/png_encoder.hpp"
#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/device/page/page_style.hpp"
#include "core/device/page/utf8.hpp"
#include "core/format_number.hpp"
#include "core/geometry/clip2d.hpp"

namespace hlr {
namespace {

const char* format_name(CairoFormat f) {
  switch (f) {
    case CairoFormat::Pdf:
      return "PDF";
    case CairoFormat::Svg:
      return "SVG";
    case CairoFormat::Png:
      return "PNG";
  }
  return "?";
}

// Everything that can be wrong with a page is found before any file exists.
void validate_page(const PlotPage& page, const CairoOptions& o, const std::string& where) {
  try {
    check_page_spec(PageSpec{{page.width_mm, page.height_mm}, page.margin_mm});
  } catch (const DeviceError& e) {
    throw DeviceError(where + e.what());
  }
  for (std::size_t s = 0; s < page.strokes.size(); ++s)
    for (const Point2& p : page.strokes[s].points)
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw DeviceError(where + "stroke " + std::to_string(s + 1) + " has a non-finite point");
  if (o.format == CairoFormat::Png) (void)png_pixel_size(page, o.dpi);
}

void validate(const std::vector<PlotPage>& pages, const CairoOptions& o) {
  if (pages.empty()) throw DeviceError("nothing to draw: no pages");
  if (o.format != CairoFormat::Pdf && pages.size() > 1)
    throw DeviceError(std::string("a ") + format_name(o.format) + " file holds one page, got " +
                      std::to_string(pages.size()) +
                      "; put a {frame} pattern in the output name to write one file per frame");
  for (std::size_t i = 0; i < pages.size(); ++i)
    validate_page(pages[i], o, pages.size() > 1 ? "page " + std::to_string(i + 1) + ": " : "");
}

// Adds one stroke to the current path, clipped to `box`; a stroke leaving and re-entering the box
// becomes several subpaths.
void add_stroke(cairo_t* cr, const PlotStroke& stroke, const Rect2& box) {
  clip_polyline_to_rect(
      stroke.points, box, [&](Point2 p) { cairo_library().cairo_move_to(cr, p.x, p.y); },
      [&](Point2 p) { cairo_library().cairo_line_to(cr, p.x, p.y); });
}

// The caption as valid UTF-8 (cairo fails the whole surface on a bad string): bad bytes become '?'.
std::string valid_utf8(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (const std::size_t n = utf8_sequence_length(s, i)) {
      out.append(s, i, n);
      i += n;
    } else {
      out += '?';
      ++i;
    }
  }
  return out;
}

// A grey of level `g` (0 black, 1 white): as a colour, or on an alpha-only surface as ink of 1 − g.
void set_grey_or_colour(cairo_t* cr, double r, double g, double b, bool ink) {
  if (ink)
    cairo_library().cairo_set_source_rgba(cr, 0, 0, 0, 1 - g);
  else
    cairo_library().cairo_set_source_rgb(cr, r, g, b);
}

// Draws one page on a context whose user unit is `units_per_mm` device units, then leaves the context
// as it found it. With `ink` the surface is alpha-only and every colour is a grey (see png_bytes).
void draw_page(cairo_t* cr, const PlotPage& page, const CairoOptions& o, double units_per_mm, bool ink) {
  const bool raster = cairo_library().cairo_surface_get_type(cairo_library().cairo_get_target(cr)) ==
                      CAIRO_SURFACE_TYPE_IMAGE;
  cairo_library().cairo_save(cr);
  cairo_library().cairo_scale(cr, units_per_mm, units_per_mm);
  cairo_library().cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_library().cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);

  if (o.decorations && page.border && !page.border->empty()) {
    const Rect2& b = *page.border;
    set_grey_or_colour(cr, kBorderGrey, kBorderGrey, kBorderGrey, ink);
    cairo_library().cairo_set_line_width(cr, 0.5 * o.pens.default_width_mm());
    cairo_library().cairo_rectangle(cr, b.xmin, b.ymin, b.width(), b.height());
    cairo_library().cairo_stroke(cr);
  }

  const Rect2 box = stroke_clip_box(page, o.pens);
  for_each_pen_run(
      page, o.pens,
      [&](const PenStyle& style, StrokeLayer layer, int level, std::size_t first, std::size_t end) {
        set_grey_or_colour(cr, style.r, style.g, style.b, ink);
        // cairo's 4 × 4-sample coverage takes a third of the time of its 256 levels
        // (bench/README.md, "PNG"); on a line a pixel wide or more no eye tells them
        // apart, on thinner ones its 16 steps show as bands.
        cairo_library().cairo_set_antialias(
            cr, raster && style.width_mm * units_per_mm >= kFastAntialiasMinPixels ? CAIRO_ANTIALIAS_FAST
                                                                                   : CAIRO_ANTIALIAS_DEFAULT);
        cairo_library().cairo_set_line_width(cr, style.width_mm);
        if (layer == StrokeLayer::Hidden) {
          const double dash[] = {dash_on_mm(style.width_mm, level), dash_off_mm(style.width_mm, level)};
          cairo_library().cairo_set_dash(cr, dash, 2, 0);
        } else {
          cairo_library().cairo_set_dash(cr, nullptr, 0, 0);
        }
        for (std::size_t i = first; i < end; ++i) add_stroke(cr, page.strokes[i], box);
        cairo_library().cairo_stroke(cr);
      });
  cairo_library().cairo_set_dash(cr, nullptr, 0, 0);
  cairo_library().cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);

  if (o.decorations && !page.caption.empty()) {
    // In the bottom margin, so a caption never moves the drawing.
    set_grey_or_colour(cr, 0, 0, 0, ink);
    cairo_library().cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                                           CAIRO_FONT_WEIGHT_NORMAL);
    cairo_library().cairo_set_font_size(cr, kCaptionPt / kPointsPerMm);
    cairo_library().cairo_move_to(cr, page.margin_mm, page.height_mm - 0.6 * page.margin_mm);
    cairo_library().cairo_show_text(cr, valid_utf8(page.caption).c_str());
  }
  cairo_library().cairo_restore(cr);
}

// Draws every page on `surface` (one show_page each), finishes it and throws on any cairo error.
// `before_page` runs before each page is drawn (the PNG paints its background there).
template <typename BeforePage>
void draw_all(cairo_surface_t* surface, std::span<const PlotPage> pages, const CairoOptions& o,
              double units_per_mm, BeforePage before_page, bool ink = false) {
  check_cairo(cairo_library().cairo_surface_status(surface));
  {
    CairoContext cr{cairo_library().cairo_create(surface)};
    for (const PlotPage& page : pages) {
      before_page(cr.p, page);
      draw_page(cr.p, page, o, units_per_mm, ink);
      if (o.format != CairoFormat::Png) cairo_library().cairo_show_page(cr.p);
    }
    check_cairo(cairo_library().cairo_status(cr.p));
  }
  if (o.format != CairoFormat::Png) {
    cairo_library().cairo_surface_finish(surface);  // writes the file's tail; errors surface here
    check_cairo(cairo_library().cairo_surface_status(surface));
  }
}

// cairo names an SVG's groups after its surfaces' serial numbers, which count every surface the process
// has made: renumbered in order of appearance, the text no longer depends on what ran before or beside.
std::string renumber_surface_ids(const std::string& svg) {
  static constexpr std::string_view kWord = "surface";
  std::string out;
  out.reserve(svg.size());
  std::map<std::string, int, std::less<>> ids;
  std::size_t i = 0;
  while (i < svg.size()) {
    const std::size_t at = svg.find(kWord, i);
    if (at == std::string::npos) break;
    std::size_t end = at + kWord.size();
    while (end < svg.size() && svg[end] >= '0' && svg[end] <= '9') ++end;
    out.append(svg, i, at + kWord.size() - i);
    if (end > at + kWord.size()) {
      const auto [it, added] = ids.emplace(svg.substr(at + kWord.size(), end - at - kWord.size()),
                                           static_cast<int>(ids.size()) + 1);
      out += std::to_string(it->second);
    }
    i = end;
  }
  out.append(svg, i, std::string::npos);
  return out;
}

std::string svg_bytes(const PlotPage& page, const CairoOptions& o) {
  std::string bytes;
  // In cairo ≥ 1.16 the document unit makes the size given here millimetres and one user unit 1 mm.
  CairoSurface surface{cairo_library().cairo_svg_surface_create_for_stream(append_to_string, &bytes,
                                                                           page.width_mm, page.height_mm)};
  check_cairo(cairo_library().cairo_surface_status(surface.p));
  cairo_library().cairo_svg_surface_set_document_unit(surface.p, CAIRO_SVG_UNIT_MM);
  draw_all(surface.p, std::span(&page, 1), o, 1, [](cairo_t*, const PlotPage&) {});
  return renumber_surface_ids(bytes);
}

// Whether every pen on the page has a colour `fits` (strokes come in runs of one pen: each run is asked
// once). Grey pens (black included) on white paper, or black ones on a transparent page, let the PNG be
// rasterised into one byte of ink a pixel and stored as grey: a quarter of the pixels' memory and of what
// deflate reads.
template <typename Fits>
bool every_pen(const PlotPage& page, const PenTable& pens, Fits&& fits) {
  int last = 0;  // pen numbers start at 1
  for (const PlotStroke& s : page.strokes) {
    if (s.pen == last) continue;
    last = s.pen;
    if (!fits(pens.style(s.pen))) return false;
  }
  return true;
}

std::string png_bytes(const PlotPage& page, const CairoOptions& o) {
  const PixelSize size = png_pixel_size(page, o.dpi);
  const bool grey = every_pen(page, o.pens, [&](const PenStyle& p) {
    return o.white_background ? p.r == p.g && p.g == p.b : p.r == 0 && p.g == 0 && p.b == 0;
  });
  // Grey pages are drawn as ink on an alpha-only surface: a pen of grey g lays ink 1 − g, replacing
  // (SOURCE) what lies under its coverage exactly as an opaque colour would over white paper.
  const cairo_format_t format = grey                 ? CAIRO_FORMAT_A8
                                : o.white_background ? CAIRO_FORMAT_RGB24
                                                     : CAIRO_FORMAT_ARGB32;
  CairoSurface surface{cairo_library().cairo_image_surface_create(format, static_cast<int>(size.width),
                                                                  static_cast<int>(size.height))};
  draw_all(
      surface.p, std::span(&page, 1), o, o.dpi / kMmPerInch,
      [&](cairo_t* cr, const PlotPage&) {
        if (grey) {
          cairo_library().cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
          return;  // a new A8 surface holds no ink
        }
        if (!o.white_background) return;  // a new image surface is transparent
        cairo_library().cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_library().cairo_paint(cr);
      },
      grey);
  cairo_library().cairo_surface_flush(surface.p);
  PngRaster raster;
  raster.data = cairo_library().cairo_image_surface_get_data(surface.p);
  raster.width = size.width;
  raster.height = size.height;
  raster.stride = cairo_library().cairo_image_surface_get_stride(surface.p);
  raster.pixels = grey ? (o.white_background ? PngPixels::InkGrey : PngPixels::InkGreyAlpha)
                       : (o.white_background ? PngPixels::Rgb : PngPixels::Rgba);
  return encode_png(raster);
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + path.string() + "'");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw std::runtime_error("write to '" + path.string() + "' failed");
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

std::optional<CairoFormat> cairo_format_for(const std::filesystem::path& target) {
  std::string ext = target.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), lower);
  if (ext == ".pdf") return CairoFormat::Pdf;
  if (ext == ".svg") return CairoFormat::Svg;
  if (ext == ".png") return CairoFormat::Png;
  return std::nullopt;
}

PixelSize png_pixel_size(const PlotPage& page, double dpi) {
  if (!(std::isfinite(dpi) && dpi > 0))
    throw DeviceError("dpi must be finite and positive, got " + format_for_message(dpi));
  const double w = page.width_mm * dpi / kMmPerInch, h = page.height_mm * dpi / kMmPerInch;
  const double pw = std::max(1.0, std::round(w)), ph = std::max(1.0, std::round(h));
  if (!(pw <= kMaxPngSide && ph <= kMaxPngSide && pw * ph <= kMaxPngMegapixels * 1e6)) {
    // The largest dpi both limits allow on this page, rounded down to be safe.
    const double by_side = kMaxPngSide * kMmPerInch / std::max(page.width_mm, page.height_mm);
    const double by_area = std::sqrt(kMaxPngMegapixels * 1e6 / (page.width_mm * page.height_mm)) * kMmPerInch;
    throw DeviceError("a " + format_for_message(page.width_mm) + " x " + format_for_message(page.height_mm) +
                      " mm page at " + format_for_message(dpi) + " dpi is " + format_for_message(pw) + " x " +
                      format_for_message(ph) + " pixels; PNG output is limited to " +
                      format_for_message(kMaxPngMegapixels) + " megapixels and " +
                      std::to_string(kMaxPngSide) + " pixels a side: lower the dpi to at most " +
                      format_for_message(std::floor(0.999 * std::min(by_side, by_area))));
  }
  return {static_cast<long>(pw), static_cast<long>(ph)};
}

void check_cairo_page(const PlotPage& page, const CairoOptions& o) { validate_page(page, o, ""); }

PdfOptions pdf_options(const CairoOptions& o) { return {o.pens, o.title, o.creation_date, o.decorations}; }

std::string cairo_page_bytes(const PlotPage& page, const CairoOptions& o) {
  if (o.format == CairoFormat::Pdf)
    throw DeviceError("cairo_page_bytes: PDF pages are made by make_pdf_page");
  validate_page(page, o, "");
  try {
    return o.format == CairoFormat::Svg ? svg_bytes(page, o) : png_bytes(page, o);
  } catch (const std::runtime_error& e) {
    throw DeviceError(e.what());
  }
}

void write_cairo(const std::filesystem::path& target, const std::vector<PlotPage>& pages,
                 const CairoOptions& o) {
  if (o.format == CairoFormat::Pdf) {
    write_pdf(target, pages, pdf_options(o));
    return;
  }
  try {
    validate(pages, o);
  } catch (const DeviceError& e) {
    throw DeviceError("cannot write '" + target.string() + "': " + e.what());
  }
  write_atomically(target, [&](const std::filesystem::path& temp) {
    write_bytes(temp, o.format == CairoFormat::Svg ? svg_bytes(pages[0], o) : png_bytes(pages[0], o));
  });
}

}  // namespace hlr
