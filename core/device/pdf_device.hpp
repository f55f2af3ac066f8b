// PDF through cairo: one page per frame, the drawing fitted and centred on the paper with one uniform
// scale (core/device/page_layout.hpp, shared with the JSON device), hidden pieces dashed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/device/page_layout.hpp"
#include "core/geometry/rect2.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

struct DrawingPage {
  std::vector<VisibleSegment> segments;
  std::optional<Rect2> frame;  // drawn as a border and used for fitting when present
  std::string caption;         // printed in the bottom margin
};

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
