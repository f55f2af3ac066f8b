// The single-stroke glyph of one character, for labels and captions (core/device/page/stroke_text.hpp).
//
// Where the strokes come from, in order:
//   - ASCII: Hershey's simplex Roman ("futural");
//   - Greek letters: Hershey's simplex Greek ("greeks"), found by their Hershey numbers (527–550
//     capitals, 627–650 small letters, in the Greek alphabet's order);
//   - ß and ° : drawn here, in the simplex style;
//   - anything Unicode decomposes (libunistring): a letter with accents is its base letter with each
//     accent drawn over or under it (grave, acute, circumflex, tilde, macron, breve, dot, diaeresis,
//     ring, double acute, caron, dot below, cedilla, ogonek); a superscript or subscript is its
//     character smaller and raised or lowered (², ³); µ is μ; a ligature or fraction is its parts;
//   - typographic quotes, dashes and the ellipsis: their ASCII forms.
// Anything else has no glyph: it is drawn as a box, and missing_glyphs() names it so a caller can warn.
//
// Font units: capitals 21 tall on the baseline y = 0, y up, x from the glyph's left edge.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/vector.hpp"

namespace hlr {

struct StrokeGlyph {
  std::vector<std::vector<Point2>> strokes;  // each at least two points
  double width = 0;                          // the advance
  bool found = true;                         // false: the box drawn for a missing character
};

// The glyph of `code_point`. Throws DeviceError when the Hershey fonts cannot be loaded.
StrokeGlyph stroke_glyph(char32_t code_point);

// The code points of UTF-8 `text` in order, an ill-formed byte read as U+FFFD.
std::u32string decode_utf8(std::string_view text);

// The characters of `text` that have no glyph, each once, in order of first appearance.
std::u32string missing_glyphs(std::string_view text);

// "U+00E9 'é'" (the character itself only when printable), for messages.
std::string describe_code_point(char32_t code_point);

}  // namespace hlr
