// How the cairo devices (PDF, SVG, PNG) draw each pen: a colour and a line width.
//
// Strokes carry a 1-based pen number (PlotStroke::pen, the HPGL `SP` number). By default the pens follow
// the HP pen carousel as hp2xx shows it — 1 black, 2 red, 3 green, 4 blue, 5 cyan, 6 magenta, 7 yellow,
// 8 black — except that pen 7 is a dark yellow (amber) so that it stays visible on white paper. Pens
// above 8 repeat the eight colours (pen 9 is drawn as pen 1). Every default pen is default_width_mm wide.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace hlr {

// sRGB components in [0, 1].
struct Colour {
  double r = 0, g = 0, b = 0;
};

struct PenStyle {
  double r = 0, g = 0, b = 0;  // sRGB in [0, 1]
  double width_mm = 0.25;
};

constexpr double kDefaultPenWidthMm = 0.25;
constexpr int kCarouselPens = 8;

// The carousel colour of `pen` at `width_mm`: pens 1..8 as above, higher pens cycling, pen 0 and
// negative pens black.
PenStyle default_pen_style(int pen, double width_mm = kDefaultPenWidthMm);

// Empty when the style is drawable, else what is wrong ("the width must be finite and positive, got -1 mm").
std::optional<std::string> pen_style_problem(const PenStyle& style);

// The styles the cairo devices draw with: the pens a script set, the carousel default for the rest.
class PenTable {
 public:
  PenTable() = default;
  // Throws std::invalid_argument unless `default_width_mm` is finite and positive.
  explicit PenTable(double default_width_mm);

  double default_width_mm() const { return default_width_mm_; }
  // The width of every pen not set; throws as the constructor does.
  void set_default_width(double width_mm);
  // Throws std::invalid_argument for a pen below 1 or a style pen_style_problem() rejects.
  void set(int pen, const PenStyle& style);
  // Sets the colour only; the width stays what style(pen) says now.
  void set_colour(int pen, const Colour& colour);
  // Sets the width only; the colour stays what style(pen) says now.
  void set_width(int pen, double width_mm);

  // The style set for `pen`, else default_pen_style(pen, default_width_mm()).
  PenStyle style(int pen) const;
  bool is_set(int pen) const { return pens_.count(pen) != 0; }

 private:
  double default_width_mm_ = kDefaultPenWidthMm;
  std::map<int, PenStyle> pens_;
};

// "#rrggbb", "#rgb" (hex digits in either case) or a name: black, white, red, green, blue, cyan, magenta,
// yellow, orange, grey/gray, brown, purple (case-insensitive; the CSS values, so "green" is #008000).
// nullopt for anything else.
std::optional<Colour> parse_colour(std::string_view text);

// The colour as a person would name it: a colour name above when it is exactly that colour (green is
// CSS green, #008000), else "#rrggbb" (lower case). parse_colour() reads either back.
std::string colour_text(const Colour& colour);

}  // namespace hlr
