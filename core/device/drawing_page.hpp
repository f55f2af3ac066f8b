// One page of the hidden-line result before layout: the pieces in picture coordinates, the camera frame
// and a caption. The runtime builds these per frame; page layout and pen planning turn them into
// PlotPages (core/device/plot_page.hpp) for the devices.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geometry/rect2.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

struct DrawingPage {
  std::vector<VisibleSegment> segments;
  std::optional<Rect2> frame;  // drawn as a border and used for fitting when present
  std::string caption;         // printed in the bottom margin
};

}  // namespace hlr
