#include "core/device/page/stroke_glyphs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/utf8.hpp"
#include "core/geometry/rect2.hpp"

extern "C" {  // the C libraries' headers have no C++ guard
#include <hersheyfont.h>
}
#include <uninorm.h>

namespace hlr {
namespace {

// ---- the Hershey fonts -----------------------------------------------------------------------------

struct FontFree {
  void operator()(hershey_font* font) const { hershey_font_free(font); }
};
using Font = std::unique_ptr<hershey_font, FontFree>;

hershey_font& load(const Font& loaded, const char* name) {
  if (!loaded)
    throw DeviceError(
        std::string("cannot load the single-stroke font '") + name +
        "' (install Debian's hershey-fonts-data), or draw text as outlines with --text outline");
  return *loaded;
}

// Loaded once, on first use, by whichever thread gets there first; read-only afterwards.
hershey_font& roman() {
  static const Font loaded(hershey_font_load("futural"));
  return load(loaded, "futural");
}
hershey_font& greek() {
  static const Font loaded(hershey_font_load("greeks"));
  return load(loaded, "greeks");
}

StrokeGlyph from_font(const hershey_glyph& g) {
  StrokeGlyph out;
  out.width = g.width;
  for (const hershey_path* path = g.paths; path; path = path->next) {
    if (path->nverts < 2) continue;
    std::vector<Point2>& stroke = out.strokes.emplace_back();
    stroke.reserve(path->nverts);
    for (unsigned short i = 0; i < path->nverts; ++i)
      stroke.push_back({1.0 * path->verts[i].x, 1.0 * path->verts[i].y});
  }
  return out;
}

// The simplex Greek glyph of Hershey number `number`, searched among the font's 96 places.
std::optional<StrokeGlyph> greek_glyph(unsigned number) {
  hershey_font& f = greek();
  for (int c = 32; c < 128; ++c)
    if (f.glyphs[c].glyphnum == number) return from_font(f.glyphs[c]);
  return std::nullopt;
}

// Α–Ω and α–ω to Hershey's simplex Greek (527–550, 627–650, the alphabet's 24 letters in order); final
// sigma is sigma.
std::optional<unsigned> hershey_greek_number(char32_t c) {
  if (c >= 0x391 && c <= 0x3a9 && c != 0x3a2) return 527 + (c - 0x391) - (c > 0x3a2 ? 1 : 0);
  if (c == 0x3c2) return 644;
  if (c >= 0x3b1 && c <= 0x3c9) return 627 + (c - 0x3b1) - (c > 0x3c2 ? 1 : 0);
  return std::nullopt;
}

// ---- strokes drawn here ----------------------------------------------------------------------------

std::vector<Point2> polygon(Point2 centre, double r, int sides) {
  std::vector<Point2> out;
  for (int k = 0; k <= sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    out.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
  }
  return out;
}

std::vector<Point2> dot(Point2 at) {  // a small square, as Hershey draws its dots
  return {{at.x - 0.5, at.y - 0.5},
          {at.x + 0.5, at.y - 0.5},
          {at.x + 0.5, at.y + 0.5},
          {at.x - 0.5, at.y + 0.5},
          {at.x - 0.5, at.y - 0.5}};
}

StrokeGlyph sharp_s() {  // ß: a stem with the ascender's bowl above a rounder bowl, 19 wide
  return {{{{4, 0},
            {4, 16},
            {5, 19},
            {7, 21},
            {10, 21},
            {12, 20},
            {13, 18},
            {13, 16},
            {12, 14},
            {9, 12},
            {12, 11},
            {14, 9},
            {15, 7},
            {15, 4},
            {14, 2},
            {12, 1},
            {10, 0},
            {8, 0}}},
          19};
}

StrokeGlyph degree() { return {{polygon({5, 18}, 2.5, 12)}, 10}; }

StrokeGlyph box() {  // what a missing character is drawn as
  return {{{{2, 0}, {14, 0}, {14, 21}, {2, 21}, {2, 0}}}, 16, false};
}

// ---- accents -----------------------------------------------------------------------------------------

Rect2 bounds_of(const StrokeGlyph& g) {
  Rect2 b = Rect2::none();
  for (const auto& s : g.strokes)
    for (const Point2& p : s) b.include(p);
  return b;
}

double top_of(const StrokeGlyph& g) { return std::max(0.0, bounds_of(g).ymax); }

// Adds the combining mark `mark` to `g`; false for a mark not drawn here. Marks above sit 2 units over the
// glyph's top (stacked marks over each other), marks below under the baseline.
bool add_mark(StrokeGlyph& g, char32_t mark) {
  const double cx = 0.5 * g.width, y = top_of(g) + 2;
  auto add = [&](std::vector<Point2> s) { g.strokes.push_back(std::move(s)); };
  switch (mark) {
    case 0x300:  // grave
      add({{cx - 1.5, y + 3.5}, {cx + 1.5, y + 0.5}});
      return true;
    case 0x301:  // acute
      add({{cx + 1.5, y + 3.5}, {cx - 1.5, y + 0.5}});
      return true;
    case 0x302:  // circumflex
      add({{cx - 3, y + 0.5}, {cx, y + 3.5}, {cx + 3, y + 0.5}});
      return true;
    case 0x303:  // tilde
      add({{cx - 3.5, y + 1},
           {cx - 2, y + 2.5},
           {cx - 0.5, y + 2},
           {cx + 0.5, y + 1},
           {cx + 2, y + 0.5},
           {cx + 3.5, y + 2}});
      return true;
    case 0x304:  // macron
      add({{cx - 3, y + 1.5}, {cx + 3, y + 1.5}});
      return true;
    case 0x306:  // breve
      add({{cx - 3, y + 3}, {cx - 2, y + 1.3}, {cx, y + 0.7}, {cx + 2, y + 1.3}, {cx + 3, y + 3}});
      return true;
    case 0x307:  // dot above
      add(dot({cx, y + 1.5}));
      return true;
    case 0x308:  // diaeresis
      add(dot({cx - 2.5, y + 1.5}));
      add(dot({cx + 2.5, y + 1.5}));
      return true;
    case 0x30a:  // ring
      add(polygon({cx, y + 2}, 1.7, 8));
      return true;
    case 0x30b:  // double acute
      add({{cx, y + 3.5}, {cx - 2, y + 0.5}});
      add({{cx + 3, y + 3.5}, {cx + 1, y + 0.5}});
      return true;
    case 0x30c:  // caron
      add({{cx - 3, y + 3.5}, {cx, y + 0.5}, {cx + 3, y + 3.5}});
      return true;
    case 0x323:  // dot below
      add(dot({cx, -2.5}));
      return true;
    case 0x327:  // cedilla
      add({{cx, 0}, {cx, -2}, {cx + 1.5, -3}, {cx + 1, -4.5}, {cx - 1.5, -5}});
      return true;
    case 0x328:  // ogonek, at the right
      add({{cx + 2, 0}, {cx, -2.5}, {cx + 1, -4.5}, {cx + 3, -4.5}});
      return true;
    default:
      return false;
  }
}

bool is_above(char32_t mark) { return mark >= 0x300 && mark <= 0x315; }

// i and j lose their dot under a mark above, as in print.
void drop_dot(StrokeGlyph& g) {
  std::erase_if(g.strokes, [](const std::vector<Point2>& s) {
    return std::all_of(s.begin(), s.end(), [](Point2 p) { return p.y > 15; });
  });
}

// ---- composition -----------------------------------------------------------------------------------

StrokeGlyph scaled(StrokeGlyph g, double factor, double raise) {
  for (auto& s : g.strokes)
    for (Point2& p : s) p = {factor * p.x, factor * p.y + raise};
  g.width *= factor;
  return g;
}

void append(StrokeGlyph& to, const StrokeGlyph& g) {
  for (const auto& s : g.strokes) {
    std::vector<Point2>& t = to.strokes.emplace_back();
    for (const Point2& p : s) t.push_back({p.x + to.width, p.y});
  }
  to.width += g.width;
  to.found = to.found && g.found;
}

std::optional<char> ascii_form(char32_t c) {
  switch (c) {
    case 0xa0:    // no-break space
    case 0x2009:  // thin space
      return ' ';
    case 0x2018:
    case 0x2019:
    case 0x201a:
      return '\'';
    case 0x201c:
    case 0x201d:
    case 0x201e:
      return '"';
    case 0x2010:
    case 0x2011:
    case 0x2012:
    case 0x2013:
    case 0x2014:
    case 0x2212:  // minus sign
      return '-';
    case 0x2044:  // fraction slash
    case 0x2215:
      return '/';
    case 0xd7:  // multiplication sign
      return 'x';
    default:
      return std::nullopt;
  }
}

StrokeGlyph glyph_of(char32_t c, int depth);

// Letters Unicode does not decompose, made from a Latin letter and a stroke across it (ø, ł, đ) or from two
// letters side by side (æ, œ).
std::optional<StrokeGlyph> made_letter(char32_t c, int depth) {
  const auto base = [&](char letter) { return glyph_of(static_cast<char32_t>(letter), depth + 1); };
  switch (c) {
    case 0xf8:  // ø, Ø: a slash through the round letter
    case 0xd8: {
      StrokeGlyph g = base(c == 0xf8 ? 'o' : 'O');
      const Rect2 b = bounds_of(g);
      g.strokes.push_back({{b.xmin - 1, b.ymin - 1}, {b.xmax + 1, b.ymax + 1}});
      return g;
    }
    case 0x142:  // ł, Ł: a short stroke across the stem
    case 0x141: {
      StrokeGlyph g = base(c == 0x142 ? 'l' : 'L');
      const double x = bounds_of(g).xmin;
      g.strokes.push_back({{x - 2.5, 7}, {x + 3, 11}});
      return g;
    }
    case 0x111: {  // đ: a bar across the ascender
      StrokeGlyph g = base('d');
      const double x = bounds_of(g).xmax;
      g.strokes.push_back({{x - 3, 17}, {x + 2, 17}});
      return g;
    }
    case 0x110: {  // Đ: a bar across the stem
      StrokeGlyph g = base('D');
      const double x = bounds_of(g).xmin;
      g.strokes.push_back({{x - 2, 10.5}, {x + 4, 10.5}});
      return g;
    }
    case 0x131: {  // ı: the i without its dot
      StrokeGlyph g = base('i');
      drop_dot(g);
      return g;
    }
    case 0xe6:  // æ, Æ, œ, Œ: the two letters
    case 0xc6:
    case 0x153:
    case 0x152: {
      const bool small = c == 0xe6 || c == 0x153;
      StrokeGlyph g = base(c == 0xe6 || c == 0xc6 ? (small ? 'a' : 'A') : (small ? 'o' : 'O'));
      append(g, base(small ? 'e' : 'E'));
      return g;
    }
    default:
      return std::nullopt;
  }
}

StrokeGlyph glyph_of(char32_t c, int depth) {
  if (c >= 0x20 && c < 0x7f) return from_font(*hershey_font_glyph(&roman(), static_cast<unsigned char>(c)));
  if (const std::optional<unsigned> n = hershey_greek_number(c))
    if (std::optional<StrokeGlyph> g = greek_glyph(*n)) return *g;
  if (c == 0xdf) return sharp_s();
  if (std::optional<StrokeGlyph> made = made_letter(c, depth)) return *made;
  if (c == 0xb0) return degree();
  if (c == 0x2026) {  // ellipsis
    StrokeGlyph g;
    for (int k = 0; k < 3; ++k) append(g, glyph_of('.', depth + 1));
    return g;
  }
  if (const std::optional<char> a = ascii_form(c)) return glyph_of(static_cast<char32_t>(*a), depth + 1);
  if (depth > 4 || c > 0x10ffff) return box();
  ucs4_t parts[UC_DECOMPOSITION_MAX_LENGTH];
  int tag = 0;
  const int n = uc_decomposition(static_cast<ucs4_t>(c), &tag, parts);
  if (n <= 0) return box();
  if (tag == UC_DECOMP_CANONICAL && n >= 2 && parts[1] >= 0x300 && parts[1] < 0x370) {
    StrokeGlyph g = glyph_of(parts[0], depth + 1);
    if (!g.found) return box();
    if ((parts[0] == 'i' || parts[0] == 'j') && is_above(parts[1])) drop_dot(g);
    for (int k = 1; k < n; ++k)
      if (!add_mark(g, parts[k])) return box();
    return g;
  }
  StrokeGlyph g;
  for (int k = 0; k < n; ++k) append(g, glyph_of(parts[k], depth + 1));
  if (!g.found) return box();
  if (tag == UC_DECOMP_SUPER) return scaled(std::move(g), 0.6, 21 - 0.6 * 21);
  if (tag == UC_DECOMP_SUB) return scaled(std::move(g), 0.6, -4);
  return g;
}

}  // namespace

StrokeGlyph stroke_glyph(char32_t code_point) { return glyph_of(code_point, 0); }

std::u32string decode_utf8(std::string_view text) {
  std::u32string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence_length(text, i);
    if (n == 0) {
      out.push_back(0xfffd);
      ++i;
      continue;
    }
    auto c = static_cast<char32_t>(static_cast<unsigned char>(text[i]) & (0xffu >> (n == 1 ? 0 : n + 1)));
    for (std::size_t k = 1; k < n; ++k) c = (c << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3fu);
    out.push_back(c);
    i += n;
  }
  return out;
}

std::u32string missing_glyphs(std::string_view text) {
  std::u32string missing;
  for (const char32_t c : decode_utf8(text))
    if (missing.find(c) == std::u32string::npos && !stroke_glyph(c).found) missing.push_back(c);
  return missing;
}

std::string describe_code_point(char32_t c) {
  char code[16];
  std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(c));
  std::string out = code;
  if (c < 0x20 || (c >= 0x7f && c < 0xa0) || c == 0xfffd || (c >= 0xd800 && c <= 0xdfff) || c > 0x10ffff)
    return out;
  // The character itself, encoded back to UTF-8.
  std::string utf8;
  if (c < 0x80) {
    utf8 += static_cast<char>(c);
  } else if (c < 0x800) {
    utf8 += static_cast<char>(0xc0 | (c >> 6));
    utf8 += static_cast<char>(0x80 | (c & 0x3f));
  } else if (c < 0x10000) {
    utf8 += static_cast<char>(0xe0 | (c >> 12));
    utf8 += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
    utf8 += static_cast<char>(0x80 | (c & 0x3f));
  } else {
    utf8 += static_cast<char>(0xf0 | (c >> 18));
    utf8 += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
    utf8 += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
    utf8 += static_cast<char>(0x80 | (c & 0x3f));
  }
  return out + " '" + utf8 + "'";
}

}  // namespace hlr
