// The built-in demo: Desens' aircraft carrier, an overview and the landing approach of the thesis's
// Figures 36–39, interpolated between the printed views.
#pragma once

#include <vector>

#include "core/device/drawing_page.hpp"
#include "core/hlr/render_frame.hpp"

namespace hlr {

struct DemoStats {
  std::size_t frames = 0, segments = 0;
  double seconds = 0;
};

std::vector<DrawingPage> render_carrier_demo(int approach_frames, const HlrOptions& options, DemoStats& stats);

}  // namespace hlr
