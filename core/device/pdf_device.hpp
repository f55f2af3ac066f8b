// PDF through cairo: one page per frame, the drawing fitted and centred on the paper with one uniform
// scale, hidden pieces dashed. (The full device set — SVG, PNG, paper sizes, pens — grows from here.)
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/rect2.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

struct DrawingPage {
  std::vector<VisibleSegment> segments;
  std::optional<Rect2> frame;  // drawn as a border and used for fitting when present
  std::string caption;         // printed under the drawing
};

struct PdfOptions {
  double page_width_mm = 297;  // A4 landscape
  double page_height_mm = 210;
  double margin_mm = 12;
  double line_width_mm = 0.25;
  std::string title;  // PDF metadata
};

void write_pdf(const std::filesystem::path& target, const std::vector<DrawingPage>& pages,
               const PdfOptions& options = {});

}  // namespace hlr
