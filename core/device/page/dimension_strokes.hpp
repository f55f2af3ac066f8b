// Dimensions on a sheet: the distance between two world points drawn as a draughtsman does — two extension
// lines from the points, a dimension line between them with open arrowheads (two strokes each, so a pen
// draws them), and the measured value in single-stroke letters along it — hidden by nothing, in a pen of
// its own. Aligned dimensions measure the true 3-D distance and run parallel to the points' picture;
// horizontal and vertical ones measure along the view's right or up direction (exact in any camera) and
// run level or upright on the page. Positive offsets put the dimension line above the points (to the left
// of an upright one). Angle dimensions measure the true 3-D angle at a vertex and draw an arc about the
// vertex's picture between the legs' pictures, with arrowheads and the value in degrees outside it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

enum class DimensionDirection { Aligned, Horizontal, Vertical };

// What a distance is written in, a world unit read as a millimetre (as the title block's scale reads it):
// mm bare, as drawings in millimetres are; the others converted and marked ("2.5 cm", "0.984\"").
enum class DimensionUnit { Mm, Cm, M, In };
std::optional<DimensionUnit> dimension_unit_named(const std::string& name);  // "mm", "cm", "m", "in"

struct PageDimension {
  Point3 from, to;               // world points
  std::optional<Point3> vertex;  // an angle's vertex: the angle from → vertex → to is measured
  std::size_t view = 0;          // the sheet's view it is drawn in
  double offset_mm = 10;         // a distance's line from the points
  double radius_mm = 15;         // an angle's arc about the vertex
  // An angle's legs that are no edge of the part (a chamfer's angle against the edge it cut off): each
  // drawn from the vertex to past the arc.
  bool extend_from = false, extend_to = false;
  DimensionDirection direction = DimensionDirection::Aligned;
  DimensionUnit unit = DimensionUnit::Mm;
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
  double value = 0;                          // what was measured: world units, or degrees
  std::string text;                          // what is written
  std::string problem;                       // non-empty: nothing drawn, and why
};

// "80", "12.5", "3.14": `value` to at most `precision` decimals, without trailing zeros.
std::string dimension_value_text(double value, int precision);
// A distance of `world` units written in `unit`: "80", "8 cm", "3.15\"".
std::string dimension_distance_text(double world, DimensionUnit unit, int precision);

// The dimension in `camera`'s picture laid out by `layout`. A point behind a perspective camera, points
// that fall within 0.1 mm of one another along the measured direction, or an angle's leg of no length or
// falling on the vertex in the picture, give a problem instead of strokes.
DimensionDrawing dimension_strokes(const PageDimension& dimension, const Camera& camera,
                                   const PageLayout& layout);

}  // namespace hlr
