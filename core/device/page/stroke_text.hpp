// Single-stroke text: letters a pen draws once, as polylines, instead of the filled outlines of a
// document font (which a plotter would trace twice, inside and out). The font is Hershey's simplex
// Roman ("futural", Debian's hershey-fonts-data, read through libhersheyfont): cap height 21 font units,
// descenders to −7, each glyph its own advance width.
//
// Text is UTF-8: Latin letters with accents, ß, °, ², ³, µ and Greek are drawn too
// (core/device/page/stroke_glyphs.hpp); a character with no glyph, an ill-formed byte or a control character
// is drawn as a box. Coordinates are page millimetres, y down, from the left end of the baseline.
#pragma once

#include <string_view>
#include <vector>

#include "core/geometry/vector.hpp"

namespace hlr {

// The depth of descenders below the baseline, per mm of cap height.
inline constexpr double kStrokeTextDescent = 7.0 / 21.0;

// The glyphs' strokes, each at least two points. Throws DeviceError when the font cannot be loaded.
std::vector<std::vector<Point2>> stroke_text(std::string_view text, Point2 baseline_start,
                                             double cap_height_mm);

// How far the text advances along its baseline. Throws as stroke_text() does.
double stroke_text_width_mm(std::string_view text, double cap_height_mm);

}  // namespace hlr
