// SVG and PNG through cairo, and PDF through core/device/formats/pdf_writer.hpp, drawing PlotPages
// (core/device/page/plot_page.hpp): every stroke where the page says, in its pen's colour and width
// (core/device/page/pen_style.hpp), in the order given, as core/device/page/page_style.hpp says a page looks.
//
// PDF holds one page per PlotPage, each its own size, with the title and creator "hlrscript" as
// metadata. SVG and PNG hold exactly one page; the runtime writes one file per frame for them (an output
// name with a {frame} pattern). SVG is sized in millimetres (width="297mm", one user unit = 1 mm); PNG
// is the page at `dpi`, antialiased, on white unless white_background is off (then transparent).
//
// Strokes are drawn with round caps and joins; hidden-layer strokes are dashed (2 mm dashes, 1.2 mm gaps
// as seen, the round caps included) in their pen's colour. With decorations the page's border (the
// camera frame) is drawn thin and grey and its caption printed in the bottom margin in 10 pt sans.
// Strokes far outside the page are clipped (cairo's fixed-point paths would wrap).
//
// Errors are DeviceError naming the target: bad pages (paper, margin, non-finite points), more than one
// page for SVG/PNG, a PNG over 100 megapixels or 32767 pixels a side, a missing directory, or cairo's
// own status text. Files are written atomically (core/device/page/atomic_file.hpp): on error nothing is left
// at the target and an existing file there is unchanged.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/device/formats/pdf_writer.hpp"
#include "core/device/page/pen_style.hpp"
#include "core/device/page/plot_page.hpp"

namespace hlr {

enum class CairoFormat { Pdf, Svg, Png };

struct CairoOptions {
  CairoFormat format = CairoFormat::Pdf;
  PenTable pens;
  double dpi = 150;              // PNG only
  std::string title;             // PDF metadata
  std::string creation_date;     // PDF metadata, ISO 8601 ("2026-12-01T12:00:00Z"); empty: now
  bool decorations = true;       // border and caption
  bool white_background = true;  // PNG only; transparent otherwise
};

// PNG limits: the pixel count and cairo's largest image side.
constexpr double kMaxPngMegapixels = 100;
constexpr int kMaxPngSide = 32767;

// The format a file name asks for: ".pdf", ".svg", ".png" in any case; nullopt for anything else.
std::optional<CairoFormat> cairo_format_for(const std::filesystem::path& target);

// The PNG's size in pixels for `page` at `dpi`: each side round(mm × dpi / 25.4), at least 1.
struct PixelSize {
  long width = 0, height = 0;
};
PixelSize png_pixel_size(const PlotPage& page, double dpi);

void write_cairo(const std::filesystem::path& target, const std::vector<PlotPage>& pages,
                 const CairoOptions& options);

// Throws DeviceError for a page write_cairo would refuse (bad size, non-finite point, PNG too large).
void check_cairo_page(const PlotPage& page, const CairoOptions& options);

// One page as the bytes of an SVG or PNG file (options.format). Throws DeviceError as write_cairo does.
std::string cairo_page_bytes(const PlotPage& page, const CairoOptions& options);

// The PDF settings of these options (PDF is written by core/device/formats/pdf_writer.hpp).
PdfOptions pdf_options(const CairoOptions& options);

}  // namespace hlr
