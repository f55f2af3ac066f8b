#include "runtime/repl/terminal_graphics.hpp"

#include <cairo.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

#include "core/device/formats/cairo_handles.hpp"
#include "core/geometry/clip2d.hpp"
#include "core/tolerance.hpp"
#include "runtime/repl/terminal_picture.hpp"

namespace hlr::runtime {
namespace {

// runtime/base/limits.hpp holds the runaway limits of an evaluation; these bound talking to a terminal.
// Terminals answer DA1 at once (a round trip over ssh included); a quarter second is unnoticeable at
// :show and long enough that a slow link still gets its real picture.
constexpr int kReplyTimeoutMs = 250;
// A terminal's two replies are a few dozen bytes; more is someone typing ahead, and we stop reading.
constexpr std::size_t kMaxReplyBytes = 512;

constexpr std::string_view kKittyQuery = "\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\";
constexpr std::string_view kDa1Query = "\x1b[c";
constexpr std::string_view kKittyReplyId = "i=31";  // the id the query above asks with
constexpr std::string_view kApcKitty = "\x1b_G";
constexpr std::string_view kStringTerminator = "\x1b\\";
constexpr std::string_view kDa1Reply = "\x1b[?";
constexpr std::string_view kSixelAttribute = "4";  // DA1 parameter: sixel graphics

// ---- replies ----

// The parameters of the first complete DA1 reply (`ESC [ ? params c`) in `reply`, if any.
std::optional<std::string_view> da1_parameters(std::string_view reply) {
  for (std::size_t at = reply.find(kDa1Reply); at != std::string_view::npos;
       at = reply.find(kDa1Reply, at + 1)) {
    const std::size_t begin = at + kDa1Reply.size();
    std::size_t end = begin;
    while (end < reply.size() && ((reply[end] >= '0' && reply[end] <= '9') || reply[end] == ';')) ++end;
    if (end < reply.size() && reply[end] == 'c') return reply.substr(begin, end - begin);
  }
  return std::nullopt;
}

bool has_sixel(std::string_view params) {
  while (true) {
    const std::size_t semi = params.find(';');
    if (params.substr(0, semi) == kSixelAttribute) return true;
    if (semi == std::string_view::npos) return false;
    params.remove_prefix(semi + 1);
  }
}

// A kitty graphics reply `ESC _G keys ; message ESC \` with our id and the message OK.
bool has_kitty_ok(std::string_view reply) {
  for (std::size_t at = reply.find(kApcKitty); at != std::string_view::npos;
       at = reply.find(kApcKitty, at + 1)) {
    const std::size_t begin = at + kApcKitty.size();
    const std::size_t end = reply.find(kStringTerminator, begin);
    if (end == std::string_view::npos) return false;
    const std::string_view body = reply.substr(begin, end - begin);
    const std::size_t semi = body.find(';');
    if (semi == std::string_view::npos || body.substr(semi + 1) != "OK") continue;
    std::string_view keys = body.substr(0, semi);
    while (!keys.empty()) {
      const std::size_t comma = keys.find(',');
      if (keys.substr(0, comma) == kKittyReplyId) return true;
      if (comma == std::string_view::npos) break;
      keys.remove_prefix(comma + 1);
    }
  }
  return false;
}

// ---- asking the terminal ----

std::optional<TerminalGraphics> graphics_override() {
  const char* value = std::getenv("HLRSCRIPT_GRAPHICS");
  if (!value) return std::nullopt;
  std::string v(value);
  for (char& c : v)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  if (v == "kitty") return TerminalGraphics::Kitty;
  if (v == "sixel") return TerminalGraphics::Sixel;
  if (v == "braille") return TerminalGraphics::Braille;
  return std::nullopt;
}

// Terminal multiplexers answer DA1 themselves and swallow graphics unless passed through.
bool inside_multiplexer() {
  if (std::getenv("TMUX")) return true;
  const char* term = std::getenv("TERM");
  if (!term) return false;
  const std::string_view t(term);
  return t.starts_with("screen") || t.starts_with("tmux");
}

// Puts a tty in raw input mode for the lifetime of the object and restores it on every path.
class RawInput {
 public:
  explicit RawInput(int fd) : fd_(fd) {
    if (::tcgetattr(fd_, &saved_) != 0) return;
    termios raw = saved_;
    raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);
    raw.c_cc[VMIN] = 0;  // reads never block: poll() does the waiting
    raw.c_cc[VTIME] = 0;
    ok_ = ::tcsetattr(fd_, TCSANOW, &raw) == 0;
  }
  ~RawInput() {
    if (ok_) ::tcsetattr(fd_, TCSANOW, &saved_);
  }
  RawInput(const RawInput&) = delete;
  RawInput& operator=(const RawInput&) = delete;
  bool ok() const { return ok_; }

 private:
  int fd_;
  termios saved_{};
  bool ok_ = false;
};

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// Reads until the DA1 reply is complete (every terminal answers DA1, after the kitty query if it
// answers that), the time is up, or too much came.
std::string read_reply(int fd) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(kReplyTimeoutMs);
  std::string reply;
  char buffer[kMaxReplyBytes];
  while (reply.size() < kMaxReplyBytes && !da1_parameters(reply)) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) break;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0 || !(p.revents & POLLIN)) break;
    const ssize_t n = ::read(fd, buffer, kMaxReplyBytes - reply.size());
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) break;
    reply.append(buffer, static_cast<std::size_t>(n));
  }
  return reply;
}

// ---- drawing ----

constexpr double kMarginPx = 2;            // keeps lines on the frame's border whole
constexpr double kLineWidthPx = 2;         // thick enough to survive the sixel threshold and small fonts
constexpr double kHiddenDash[2] = {6, 4};  // on, off (pixels)
constexpr double kHiddenGrey = 0.45;
// Sixel has two colours: a pixel is ink when darker than this (hidden grey included).
constexpr double kInkThreshold = 0.7;

// Adds the segments whose hidden flag is `hidden` to the path, clipped to a little more than the
// surface so that cairo's fixed-point coordinates never overflow.
void add_segments(cairo_t* cr, const std::vector<VisibleSegment>& segments, const PictureFit& fit,
                  bool hidden, int width, int height) {
  const Rect2 bounds{-kMarginPx, -kMarginPx, width + kMarginPx, height + kMarginPx};
  for (const VisibleSegment& s : segments) {
    if (s.hidden != hidden) continue;
    const Point2 a = fit.map(s.s0), b = fit.map(s.s1);
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) continue;
    const auto range = clip_segment_to_rect(a, b, bounds);
    if (!range) continue;
    const double dx = b.x - a.x, dy = b.y - a.y;
    cairo_library().cairo_move_to(cr, a.x + range->first * dx, a.y + range->first * dy);
    cairo_library().cairo_line_to(cr, a.x + range->second * dx, a.y + range->second * dy);
  }
}

// Sixel wants hard pixels; the PNG may be smooth.
void draw(cairo_surface_t* surface, const std::vector<VisibleSegment>& segments,
          const std::optional<Rect2>& frame, int width, int height, bool antialias) {
  CairoContext cr{cairo_library().cairo_create(surface)};
  cairo_library().cairo_set_source_rgb(cr.p, 1, 1, 1);
  cairo_library().cairo_paint(cr.p);
  const PictureFit fit = fit_picture(segments, frame, width - 2 * kMarginPx, height - 2 * kMarginPx);
  if (!fit.box.empty()) {
    cairo_library().cairo_translate(cr.p, kMarginPx, kMarginPx);
    cairo_library().cairo_set_antialias(cr.p, antialias ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
    cairo_library().cairo_set_line_width(cr.p, kLineWidthPx);
    cairo_library().cairo_set_line_cap(cr.p, CAIRO_LINE_CAP_ROUND);
    // Hidden first, so that visible lines win where they cross.
    cairo_library().cairo_set_source_rgb(cr.p, kHiddenGrey, kHiddenGrey, kHiddenGrey);
    cairo_library().cairo_set_dash(cr.p, kHiddenDash, static_cast<int>(std::size(kHiddenDash)), 0);
    add_segments(cr.p, segments, fit, true, width, height);
    cairo_library().cairo_stroke(cr.p);
    cairo_library().cairo_set_source_rgb(cr.p, 0, 0, 0);
    cairo_library().cairo_set_dash(cr.p, nullptr, 0, 0);
    add_segments(cr.p, segments, fit, false, width, height);
    cairo_library().cairo_stroke(cr.p);
  }
  check_cairo(cairo_library().cairo_status(cr.p));
  cairo_library().cairo_surface_flush(surface);
}

constexpr char kBase64Alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr unsigned kSextetMask = 0x3f;
constexpr int kSextetBits = 6;
constexpr std::size_t kBase64Group = 3;  // bytes per four base64 characters

std::string base64(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + kBase64Group - 1) / kBase64Group * (kBase64Group + 1));
  std::size_t i = 0;
  auto byte = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(bytes[k])); };
  for (; i + kBase64Group <= bytes.size(); i += kBase64Group) {
    const unsigned v = byte(i) << (2 * CHAR_BIT) | byte(i + 1) << CHAR_BIT | byte(i + 2);
    for (int shift = 3 * kSextetBits; shift >= 0; shift -= kSextetBits)
      out += kBase64Alphabet[(v >> shift) & kSextetMask];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    const unsigned v = byte(i) << (2 * CHAR_BIT) | (rest > 1 ? byte(i + 1) << CHAR_BIT : 0u);
    out += kBase64Alphabet[(v >> (3 * kSextetBits)) & kSextetMask];
    out += kBase64Alphabet[(v >> (2 * kSextetBits)) & kSextetMask];
    out += rest > 1 ? kBase64Alphabet[(v >> kSextetBits) & kSextetMask] : '=';
    out += '=';
  }
  return out;
}

// Kitty graphics protocol: the PNG (f=100) transmitted and shown at the cursor (a=T) in chunks of at
// most 4096 base64 characters; m=1 while more follow. q=2: no reply lands in the REPL's input.
constexpr std::size_t kKittyChunk = 4096;

std::string kitty_image(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                        int width, int height) {
  CairoSurface surface{cairo_library().cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)};
  check_cairo(cairo_library().cairo_surface_status(surface.p));
  draw(surface.p, segments, frame, width, height, true);
  std::string png;
  check_cairo(cairo_library().cairo_surface_write_to_png_stream(surface.p, append_to_string, &png));
  const std::string data = base64(png);
  std::string out;
  for (std::size_t at = 0; at < data.size(); at += kKittyChunk) {
    const bool last = at + kKittyChunk >= data.size();
    out += kApcKitty;
    if (at == 0) out += "a=T,f=100,q=2,";
    out += last ? "m=0;" : "m=1;";
    out.append(data, at, kKittyChunk);
    out += kStringTerminator;
  }
  out += '\n';
  return out;
}

// Sixel: each band is six pixel rows; a data character is '?' plus one bit per row of its column.
constexpr int kSixelRows = 6;
constexpr char kSixelBase = '?';
constexpr int kMinRun = 4;  // "!4x" is shorter than "xxxx"; shorter runs are written out
constexpr unsigned kChannelMask = 0xff;
constexpr double kChannelMax = 255;

void put_run(std::string& out, char c, int n) {
  if (n >= kMinRun) {
    out += '!';
    out += std::to_string(n);
    out += c;
  } else {
    out.append(static_cast<std::size_t>(n), c);
  }
}

std::string sixel_image(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                        int width, int height) {
  CairoSurface surface{cairo_library().cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)};
  check_cairo(cairo_library().cairo_surface_status(surface.p));
  draw(surface.p, segments, frame, width, height, false);
  const unsigned char* data = cairo_library().cairo_image_surface_get_data(surface.p);
  const int stride = cairo_library().cairo_image_surface_get_stride(surface.p);
  auto ink = [&](int x, int y) {  // RGB24: one native-endian 32-bit word per pixel, green in bits 8–15
    std::uint32_t px;
    std::copy_n(data + static_cast<std::ptrdiff_t>(y) * stride +
                    static_cast<std::ptrdiff_t>(x) * static_cast<std::ptrdiff_t>(sizeof px),
                sizeof px, reinterpret_cast<unsigned char*>(&px));
    return ((px >> CHAR_BIT) & kChannelMask) < kInkThreshold * kChannelMax;
  };

  // DCS q (default aspect, background painted explicitly), raster attributes, white #0 and black #1.
  std::string out = "\x1bPq\"1;1;" + std::to_string(width) + ";" + std::to_string(height);
  out += "#0;2;100;100;100#1;2;0;0;0";
  std::vector<char> column(static_cast<std::size_t>(width));
  for (int top = 0; top < height; top += kSixelRows) {
    const int rows = std::min(kSixelRows, height - top);
    // The band's white, limited to the rows the image has, then its ink over it.
    out += "#0";
    put_run(out, static_cast<char>(kSixelBase + (1 << rows) - 1), width);
    bool any = false;
    for (int x = 0; x < width; ++x) {
      int bits = 0;
      for (int r = 0; r < rows; ++r)
        if (ink(x, top + r)) bits |= 1 << r;
      column[static_cast<std::size_t>(x)] = static_cast<char>(kSixelBase + bits);
      any = any || bits != 0;
    }
    if (any) {
      out += "$#1";
      int end = width;
      while (column[static_cast<std::size_t>(end - 1)] == kSixelBase) --end;  // trailing blanks
      for (int x = 0; x < end;) {
        int n = 1;
        while (x + n < end && column[static_cast<std::size_t>(x + n)] == column[static_cast<std::size_t>(x)])
          ++n;
        put_run(out, column[static_cast<std::size_t>(x)], n);
        x += n;
      }
    }
    if (top + kSixelRows < height) out += '-';
  }
  out += kStringTerminator;
  out += '\n';
  return out;
}

}  // namespace

TerminalGraphics parse_graphics_reply(std::string_view reply) {
  if (has_kitty_ok(reply)) return TerminalGraphics::Kitty;
  if (const auto params = da1_parameters(reply); params && has_sixel(*params)) return TerminalGraphics::Sixel;
  return TerminalGraphics::Braille;
}

TerminalGraphics detect_terminal_graphics(int in_fd, int out_fd) {
  if (const auto chosen = graphics_override()) return *chosen;
  if (!::isatty(in_fd) || !::isatty(out_fd) || inside_multiplexer()) return TerminalGraphics::Braille;
  const RawInput raw(in_fd);
  if (!raw.ok()) return TerminalGraphics::Braille;
  std::string query(kKittyQuery);
  query += kDa1Query;
  if (!write_all(out_fd, query)) return TerminalGraphics::Braille;
  return parse_graphics_reply(read_reply(in_fd));
}

std::string terminal_image(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                           TerminalGraphics kind, int width_px, int height_px) {
  // Scaled down as a whole, so the area keeps the terminal's proportions.
  const double w = std::max(width_px, 1), h = std::max(height_px, 1);
  const double shrink = std::min({1.0, kMaxTerminalImageWidth / w, kMaxTerminalImageHeight / h});
  const int width = std::clamp(static_cast<int>(std::lround(w * shrink)), 1, kMaxTerminalImageWidth);
  const int height = std::clamp(static_cast<int>(std::lround(h * shrink)), 1, kMaxTerminalImageHeight);
  switch (kind) {
    case TerminalGraphics::Kitty:
      return kitty_image(segments, frame, width, height);
    case TerminalGraphics::Sixel:
      return sixel_image(segments, frame, width, height);
    case TerminalGraphics::Braille:
      break;
  }
  return braille_picture(segments, frame, std::max(1, width_px / kAssumedCellWidthPx),
                         std::max(1, height_px / kAssumedCellHeightPx));
}

PixelSize terminal_pixels(int fd, int columns, int rows) {
  columns = std::max(columns, 1);
  const int picture_rows = std::max(rows - kTextRowsBelowPicture, 1);
  winsize ws{};
  if (::ioctl(fd, TIOCGWINSZ, &ws) == 0 && ws.ws_xpixel > 0 && ws.ws_ypixel > 0 && ws.ws_col > 0 &&
      ws.ws_row > 0) {
    // The share of the tty's pixels that the cells asked for cover (never more than the tty has).
    const long w = long{ws.ws_xpixel} * std::min<long>(columns, ws.ws_col) / ws.ws_col;
    const long h = long{ws.ws_ypixel} * std::min<long>(picture_rows, ws.ws_row) / ws.ws_row;
    return {static_cast<int>(std::max(w, 1L)), static_cast<int>(std::max(h, 1L))};
  }
  return {columns * kAssumedCellWidthPx, picture_rows * kAssumedCellHeightPx};
}

}  // namespace hlr::runtime
