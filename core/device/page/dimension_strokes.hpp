// Dimensions on a sheet: the distance between two world points drawn as a draughtsman does — two extension
// lines from the points, a dimension line between them with open arrowheads (two strokes each, so a pen
// draws them), and the measured value in single-stroke letters along it — hidden by nothing, in a pen of
// its own. Aligned dimensions measure the true 3-D distance and run parallel to the points' picture;
// horizontal and vertical ones measure along the view's right or up direction (exact in any camera) and
// run level or upright on the page. Positive offsets put the dimension line above the points (to the left
// of an upright one).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

enum class DimensionDirection { Aligned, Horizontal, Vertical };

struct PageDimension {
  Point3 from, to;       // world points
  std::size_t view = 0;  // the sheet's view it is drawn in
  double offset_mm = 10;
  DimensionDirection direction = DimensionDirection::Aligned;
  std::optional<std::string> text;  // instead of the measured value
  int precision = 2;                // decimals at most (trailing zeros dropped)
  int pen = 1;
  double cap_mm = 3.5;  // the value's letters
};

// Arrowheads: 3 mm long, 15° either side of the line. Extension lines: 1.5 mm clear of the point, 2 mm past
// the dimension line.
inline constexpr double kArrowMm = 3, kArrowHalfAngleDeg = 15, kExtensionGapMm = 1.5, kExtensionOverMm = 2;

struct DimensionDrawing {
  std::vector<std::vector<Point2>> strokes;  // page mm
  double value = 0;                          // what was measured, world units
  std::string text;                          // what is written
  std::string problem;                       // non-empty: nothing drawn, and why
};

// "80", "12.5", "3.14": `value` to at most `precision` decimals, without trailing zeros.
std::string dimension_value_text(double value, int precision);

// The dimension in `camera`'s picture laid out by `layout`. A point behind a perspective camera, or points
// that fall within 0.1 mm of one another along the measured direction, give a problem instead of strokes.
DimensionDrawing dimension_strokes(const PageDimension& dimension, const Camera& camera,
                                   const PageLayout& layout);

}  // namespace hlr
