// The real picture in the terminal: terminals that speak the kitty graphics protocol get a PNG, those
// that speak sixel get a two-colour sixel image, and every other terminal the braille picture of
// runtime/repl/terminal_picture.hpp. Which one is decided by asking the terminal (or by $HLRSCRIPT_GRAPHICS).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/rect2.hpp"
#include "core/hlr/visible_segment.hpp"
#include "runtime/repl/terminal_picture.hpp"

namespace hlr::runtime {

enum class TerminalGraphics { Braille, Kitty, Sixel };

// Bounds of the image terminal_image draws: larger requests are scaled down, keeping proportions, so a
// huge terminal never costs more than this many pixels (about 0.5 MB of base64 PNG at worst).
inline constexpr int kMaxTerminalImageWidth = 1600;
inline constexpr int kMaxTerminalImageHeight = 1200;

// The cell size assumed when the terminal does not report its pixels (a common 10 × 20 font).
inline constexpr int kAssumedCellWidthPx = 10;
inline constexpr int kAssumedCellHeightPx = 20;
// Text rows kept free under the picture (the prompt and the line after it).
inline constexpr int kTextRowsBelowPicture = 2;

// What the terminal's answer to the queries of detect_terminal_graphics says: Kitty for a kitty
// graphics reply `ESC _G i=31;OK ESC \`, Sixel for a primary device attributes reply `ESC [ ? … c`
// with the parameter 4, Braille for anything else. Kitty wins over sixel.
TerminalGraphics parse_graphics_reply(std::string_view reply);

// $HLRSCRIPT_GRAPHICS=kitty|sixel|braille decides when set (other values are ignored). Otherwise
// Braille unless both descriptors are terminals and not inside tmux or screen; then the terminal is
// asked (kitty graphics query, then DA1) and its reply parsed, waiting at most about a quarter second.
TerminalGraphics detect_terminal_graphics(int in_fd, int out_fd);

// The escape sequence that shows the drawing (black lines on white, hidden pieces dashed — and grey in
// the PNG; sixel has only black and white),
// width_px × height_px pixels (bounded as above), fitted as fit_picture does, ending in a newline.
// Braille gives braille_picture with the assumed cell size. Throws std::runtime_error if cairo fails.
std::string terminal_image(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                           TerminalGraphics kind, int width_px, int height_px);

// The pixels available for a picture in the terminal on `fd` of `columns` × `rows` cells: the size the
// tty reports (TIOCGWINSZ), else the assumed cell size; less kTextRowsBelowPicture rows. At least 1 × 1.
struct PixelSize {
  int width, height;
};
PixelSize terminal_pixels(int fd, int columns, int rows);

}  // namespace hlr::runtime
