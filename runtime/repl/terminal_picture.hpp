// A drawing in the terminal, in Unicode braille: every character cell is 2 × 4 dots (U+2800 + one bit
// per dot), so a 80 × 24 terminal shows a 160 × 96-dot picture, and dots are about square in common
// terminal fonts. Lines are stepped dot by dot; hidden pieces are drawn every other dot.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geometry/rect2.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr::runtime {

struct TerminalSize {
  int columns = 80, rows = 24;
};

// The terminal's size from the tty on `fd`, else $COLUMNS/$LINES, else 80 × 24.
TerminalSize terminal_size(int fd);

// The placement of picture coordinates (x right, y up) in a width × height area (x right, y down):
// the box — `frame` when given and not empty, else the segments' bounds — scaled to fit, keeping its
// proportions, and centred. Empty `box` when there is nothing to fit.
struct PictureFit {
  Rect2 box = Rect2::none();
  double scale = 1, ox = 0, oy = 0;
  Point2 map(Point2 p) const { return {ox + (p.x - box.xmin) * scale, oy + (box.ymax - p.y) * scale}; }
};
PictureFit fit_picture(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                       double width, double height);

// `rows` lines of `columns` braille characters each ending in '\n'. The picture is fitted to `frame`
// (the camera's) when given, else to the pieces, keeping its proportions, and centred.
std::string braille_picture(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                            int columns, int rows);

}  // namespace hlr::runtime
