// PDF through cairo: one page per frame, the drawing fitted and centred on the paper with one uniform
// scale (core/device/page_layout.hpp, shared with the JSON device), hidden pieces dashed.
//
// Superseded by core/device/cairo_device.hpp (PDF, SVG and PNG from PlotPages); kept only until the
// runtime switches over, then deleted. DrawingPage now lives in core/device/drawing_page.hpp.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/device/drawing_page.hpp"
#include "core/device/page_layout.hpp"

namespace hlr {

struct PdfOptions {
  double page_width_mm = 297;  // A4 landscape
  double page_height_mm = 210;
  double margin_mm = 12;
  double line_width_mm = 0.25;
  std::string title;  // PDF metadata

  PageSpec page_spec() const { return {{page_width_mm, page_height_mm}, margin_mm}; }
};

void write_pdf(const std::filesystem::path& target, const std::vector<DrawingPage>& pages,
               const PdfOptions& options = {});

}  // namespace hlr
