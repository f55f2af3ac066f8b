#include "core/device/page/pen_style.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/format_number.hpp"

namespace hlr {
namespace {

// hp2xx's default pen colours (its -c palette), pen 7 darkened from #ffff00 to an amber.
constexpr std::array<Colour, kCarouselPens> kCarousel{{
    {0, 0, 0},      // 1 black
    {1, 0, 0},      // 2 red
    {0, 1, 0},      // 3 green
    {0, 0, 1},      // 4 blue
    {0, 1, 1},      // 5 cyan
    {1, 0, 1},      // 6 magenta
    {0.8, 0.6, 0},  // 7 yellow, dark enough for white paper
    {0, 0, 0},      // 8 black
}};

struct NamedColour {
  std::string_view name;
  unsigned rgb;
};

// CSS colour keywords.
constexpr std::array<NamedColour, 13> kNames{{
    {"black", 0x000000},
    {"white", 0xffffff},
    {"red", 0xff0000},
    {"green", 0x008000},
    {"blue", 0x0000ff},
    {"cyan", 0x00ffff},
    {"magenta", 0xff00ff},
    {"yellow", 0xffff00},
    {"orange", 0xffa500},
    {"grey", 0x808080},
    {"gray", 0x808080},
    {"brown", 0xa52a2a},
    {"purple", 0x800080},
}};

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

int hex_digit(char c) {
  c = lower(c);
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

Colour from_rgb(unsigned rgb) {
  return {((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0};
}

bool unit_interval(double v) { return v >= 0 && v <= 1; }  // false for NaN

std::string number(double v) { return format_for_message(v); }

void check_pen(int pen) {
  if (pen < 1) throw std::invalid_argument("pen numbers start at 1, got " + std::to_string(pen));
}

}  // namespace

PenStyle default_pen_style(int pen, double width_mm) {
  const Colour c = pen >= 1 ? kCarousel[static_cast<std::size_t>((pen - 1) % kCarouselPens)] : Colour{};
  return {c.r, c.g, c.b, width_mm};
}

std::optional<std::string> pen_style_problem(const PenStyle& s) {
  if (!(std::isfinite(s.width_mm) && s.width_mm > 0))
    return "the width must be finite and positive, got " + number(s.width_mm) + " mm";
  if (!(unit_interval(s.r) && unit_interval(s.g) && unit_interval(s.b)))
    return "colour components must be from 0 to 1, got (" + number(s.r) + ", " + number(s.g) + ", " +
           number(s.b) + ")";
  return std::nullopt;
}

PenTable::PenTable(double default_width_mm) { set_default_width(default_width_mm); }

void PenTable::set_default_width(double width_mm) {
  if (!(std::isfinite(width_mm) && width_mm > 0))
    throw std::invalid_argument("the default pen width must be finite and positive, got " + number(width_mm) +
                                " mm");
  default_width_mm_ = width_mm;
}

void PenTable::set(int pen, const PenStyle& style) {
  check_pen(pen);
  if (const auto problem = pen_style_problem(style))
    throw std::invalid_argument("pen " + std::to_string(pen) + ": " + *problem);
  pens_[pen] = style;
}

void PenTable::set_colour(int pen, const Colour& colour) {
  PenStyle s = style(pen);
  s.r = colour.r;
  s.g = colour.g;
  s.b = colour.b;
  set(pen, s);
}

void PenTable::set_width(int pen, double width_mm) {
  PenStyle s = style(pen);
  s.width_mm = width_mm;
  set(pen, s);
}

PenStyle PenTable::style(int pen) const {
  const auto it = pens_.find(pen);
  return it != pens_.end() ? it->second : default_pen_style(pen, default_width_mm_);
}

std::optional<Colour> parse_colour(std::string_view text) {
  if (!text.empty() && text.front() == '#') {
    text.remove_prefix(1);
    if (text.size() != 3 && text.size() != 6) return std::nullopt;
    unsigned rgb = 0;
    for (const char c : text) {
      const int d = hex_digit(c);
      if (d < 0) return std::nullopt;
      // "#rgb" is "#rrggbb" with each digit doubled, as in CSS.
      rgb = text.size() == 3 ? (rgb << 8) | static_cast<unsigned>(d * 17)
                             : (rgb << 4) | static_cast<unsigned>(d);
    }
    return from_rgb(rgb);
  }
  for (const NamedColour& n : kNames) {
    if (n.name.size() != text.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < text.size() && same; ++i) same = lower(text[i]) == n.name[i];
    if (same) return from_rgb(n.rgb);
  }
  return std::nullopt;
}

std::string colour_text(const Colour& colour) {
  const auto byte = [](double v) { return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  const unsigned rgb = byte(colour.r) << 16 | byte(colour.g) << 8 | byte(colour.b);
  for (const NamedColour& n : kNames)
    if (n.rgb == rgb) return std::string(n.name);
  char text[16];
  std::snprintf(text, sizeof text, "#%06x", rgb & 0xffffffu);
  return text;
}

}  // namespace hlr
