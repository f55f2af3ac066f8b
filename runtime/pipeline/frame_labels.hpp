// A frame's labels (`label TEXT at POINT`, runtime/eval/frame_scene.hpp) made into what the engine and the
// page draw.
//
// A world label is single-stroke text (core/device/page/stroke_text.hpp) whose baseline starts where its
// point projects, upright on the page and `size` mm tall there. To be hidden exactly as the solids hide it,
// its letters become free lines of a solid in world space: every page point of a letter is carried back
// through the page layout and the camera to the depth of the label's point (the plane through the point
// facing the camera), so the engine projects each line to where it was laid out and cuts it where faces
// lie in front of it. A label whose point is behind the eye, or at the near plane, is not drawn.
//
// The letters' size on the page needs the page layout, and the layout fits the drawing: the camera's frame
// when it has one (known before the engine runs; labels beyond it are cut there, as edges are), else the
// solids' visible pieces and the labels' text together (with_label_boxes), so that every label is on the
// page. The layout is then fixed before the labels go through the engine (PagePlotOptions::extent).
#pragma once

#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/device/page/page_plot.hpp"
#include "core/hlr/scene.hpp"
#include "runtime/eval/frame_scene.hpp"

namespace hlr::runtime {

bool has_world_labels(const std::vector<LabelSetting>& labels);

// The world labels as scene objects of free lines, named "label 1", "label 2", … (their place among the
// labels), with their pens in `pens` (parallel). Labels with empty text or behind the eye are skipped.
void add_world_labels(const std::vector<LabelSetting>& labels, const Camera& camera, const PageLayout& layout,
                      Scene& scene, std::vector<int>& pens);

// `extent` (picture units) grown to hold each world label's text at the scale the resulting layout gives:
// the text's size is fixed on the page, so its size in the picture depends on the fit (the largest scale
// at which everything fits, found by bisection). A text wider than the page itself runs off it.
Rect2 with_label_boxes(Rect2 extent, const std::vector<LabelSetting>& labels, const Camera& camera,
                       const PageSpec& spec);

// The page labels, as PagePlotOptions takes them.
std::vector<PageText> page_labels(const std::vector<LabelSetting>& labels);

}  // namespace hlr::runtime
