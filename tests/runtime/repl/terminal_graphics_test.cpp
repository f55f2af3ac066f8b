// Terminal graphics without a terminal: replies written by hand, the kitty image decoded back to its
// PNG (and the PNG to pixels with cairo), the sixel image decoded by a small sixel reader, and the
// $HLRSCRIPT_GRAPHICS override on descriptors that are not ttys.
#include "runtime/repl/terminal_graphics.hpp"

#include <cairo.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "runtime/repl/terminal_picture.hpp"

namespace hlr::runtime {
namespace {

constexpr int kWidth = 120, kHeight = 90;
constexpr int kSlackPx = 3;  // the fitting keeps a small margin; edges are looked for this close

VisibleSegment segment(double x0, double y0, double x1, double y1, bool hidden = false) {
  VisibleSegment s;
  s.s0 = {x0, y0};
  s.s1 = {x1, y1};
  s.hidden = hidden;
  return s;
}

// A cube seen head-on: its front face, a square from (-1, -1) to (1, 1), in a frame twice its size.
std::vector<VisibleSegment> square() {
  return {segment(-1, -1, 1, -1), segment(1, -1, 1, 1), segment(1, 1, -1, 1), segment(-1, 1, -1, -1)};
}
const Rect2 kFrame{-2, -2, 2, 2};

// ---- a picture as pixels, whatever it came from ----

struct Picture {
  int width = 0, height = 0;
  std::vector<bool> ink;
  bool at(int x, int y) const { return ink[static_cast<std::size_t>(y * width + x)]; }
  bool ink_near(int x, int y) const {
    for (int dy = -kSlackPx; dy <= kSlackPx; ++dy)
      for (int dx = -kSlackPx; dx <= kSlackPx; ++dx)
        if (at(x + dx, y + dy)) return true;
    return false;
  }
};

// The square of kFrame in a width × height picture: ink on its four edges, none inside or in the corners.
void expect_square(const Picture& p) {
  const int cx = p.width / 2, cy = p.height / 2, half = std::min(p.width, p.height) / 4;
  EXPECT_TRUE(p.ink_near(cx - half, cy)) << "left edge";
  EXPECT_TRUE(p.ink_near(cx + half, cy)) << "right edge";
  EXPECT_TRUE(p.ink_near(cx, cy - half)) << "top edge";
  EXPECT_TRUE(p.ink_near(cx, cy + half)) << "bottom edge";
  EXPECT_TRUE(p.ink_near(cx - half, cy - half)) << "corner";
  for (int dy = -half / 2; dy <= half / 2; ++dy)
    for (int dx = -half / 2; dx <= half / 2; ++dx) ASSERT_FALSE(p.at(cx + dx, cy + dy)) << "inside";
  EXPECT_FALSE(p.at(0, 0));
  EXPECT_FALSE(p.at(p.width - 1, p.height - 1));
  EXPECT_FALSE(p.at(cx - 2 * half + kSlackPx, cy)) << "outside, left of the square";
}

// A hidden piece is dashed: along it, both ink and gaps.
void expect_dashed_row(const Picture& p, int y, int x0, int x1) {
  int ink = 0, gaps = 0;
  for (int x = x0; x <= x1; ++x) (p.at(x, y) ? ink : gaps) += 1;
  EXPECT_GT(ink, 0);
  EXPECT_GT(gaps, 0);
}

// ---- kitty: chunks → base64 → PNG → pixels ----

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

std::string base64_decode(const std::string& text) {
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    const int v = base64_value(c);
    EXPECT_GE(v, 0) << "not base64: " << static_cast<int>(c);
    if (v < 0) return out;
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += static_cast<char>((bits >> count) & 0xff);
    }
  }
  return out;
}

struct KittyChunk {
  std::string keys, payload;
};

std::vector<KittyChunk> kitty_chunks(const std::string& image) {
  std::vector<KittyChunk> chunks;
  std::size_t at = 0;
  while (at < image.size() && image.compare(at, 3, "\x1b_G") == 0) {
    const std::size_t semi = image.find(';', at), end = image.find("\x1b\\", at);
    EXPECT_NE(semi, std::string::npos);
    EXPECT_NE(end, std::string::npos);
    if (semi == std::string::npos || end == std::string::npos || semi > end) return chunks;
    chunks.push_back({image.substr(at + 3, semi - at - 3), image.substr(semi + 1, end - semi - 1)});
    at = end + 2;
  }
  EXPECT_EQ(image.substr(at), "\n");
  return chunks;
}

std::string kitty_png(const std::string& image) {
  const std::vector<KittyChunk> chunks = kitty_chunks(image);
  EXPECT_FALSE(chunks.empty());
  std::string data;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const bool last = i + 1 == chunks.size();
    EXPECT_NE(chunks[i].keys.find(last ? "m=0" : "m=1"), std::string::npos) << chunks[i].keys;
    EXPECT_EQ(chunks[i].keys.find("a=T,f=100") != std::string::npos, i == 0) << chunks[i].keys;
    EXPECT_LE(chunks[i].payload.size(), 4096u);
    data += chunks[i].payload;
  }
  return base64_decode(data);
}

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

void expect_png_size(const std::string& png, int width, int height) {
  ASSERT_GE(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(big_endian(png, 16), static_cast<std::uint32_t>(width));
  EXPECT_EQ(big_endian(png, 20), static_cast<std::uint32_t>(height));
}

struct PngReader {
  const std::string* bytes;
  std::size_t at = 0;
};

cairo_status_t read_png(void* closure, unsigned char* data, unsigned int length) {
  auto* r = static_cast<PngReader*>(closure);
  if (r->at + length > r->bytes->size()) return CAIRO_STATUS_READ_ERROR;
  std::copy_n(r->bytes->data() + r->at, length, data);
  r->at += length;
  return CAIRO_STATUS_SUCCESS;
}

// Ink: clearly darker than white (the hidden grey included).
Picture png_picture(const std::string& png) {
  PngReader reader{&png};
  cairo_surface_t* s = cairo_image_surface_create_from_png_stream(read_png, &reader);
  Picture p;
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    cairo_surface_flush(s);
    p.width = cairo_image_surface_get_width(s);
    p.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x) {
        std::uint32_t px;
        std::copy_n(data + y * stride + 4 * x, 4, reinterpret_cast<unsigned char*>(&px));
        p.ink.push_back(((px >> 8) & 0xff) < 200);  // green channel
      }
  }
  cairo_surface_destroy(s);
  EXPECT_GT(p.width, 0) << "the PNG did not load";
  return p;
}

// ---- sixel: a small reader for what terminal_image writes ----

struct Sixel {
  int raster_width = -1, raster_height = -1;
  Picture picture;
  std::vector<int> colour;  // per pixel, -1 where nothing was painted
};

Sixel decode_sixel(const std::string& image) {
  Sixel out;
  EXPECT_EQ(image.substr(0, 3), "\x1bPq");
  const std::size_t end = image.rfind("\x1b\\");
  EXPECT_NE(end, std::string::npos);
  EXPECT_EQ(image.substr(end), "\x1b\\\n");
  std::size_t i = 3;
  auto number = [&] {
    int v = 0;
    while (i < end && image[i] >= '0' && image[i] <= '9') v = v * 10 + (image[i++] - '0');
    return v;
  };
  auto numbers = [&] {  // "a;b;c" after the introducer
    std::vector<int> v{number()};
    while (i < end && image[i] == ';') ++i, v.push_back(number());
    return v;
  };
  int x = 0, band = 0, current = 0;
  auto put = [&](char c, int n) {
    const int bits = c - '?';
    for (int k = 0; k < n; ++k, ++x)
      for (int r = 0; r < 6; ++r) {
        if (!(bits & (1 << r))) continue;
        const int y = 6 * band + r;
        EXPECT_LT(x, out.raster_width);
        EXPECT_LT(y, out.raster_height);
        if (x >= out.raster_width || y >= out.raster_height) continue;
        out.colour[static_cast<std::size_t>(y * out.raster_width + x)] = current;
      }
  };
  while (i < end) {
    const char c = image[i++];
    if (c == '"') {
      const std::vector<int> v = numbers();
      EXPECT_EQ(v.size(), 4u);
      if (v.size() != 4) break;
      EXPECT_EQ(v[0], 1);  // square pixels
      EXPECT_EQ(v[1], 1);
      out.raster_width = v[2];
      out.raster_height = v[3];
      out.colour.assign(static_cast<std::size_t>(v[2] * v[3]), -1);
    } else if (c == '#') {
      const std::vector<int> v = numbers();
      if (v.size() == 1) current = v[0];  // else a definition (#n;2;r;g;b)
    } else if (c == '!') {
      const int n = number();
      put(image[i++], n);
    } else if (c == '$') {
      x = 0;
    } else if (c == '-') {
      x = 0;
      ++band;
    } else if (c >= '?' && c <= '~') {
      put(c, 1);
    } else {
      ADD_FAILURE() << "unexpected sixel byte " << static_cast<int>(c);
    }
  }
  out.picture.width = out.raster_width;
  out.picture.height = out.raster_height;
  for (int v : out.colour) out.picture.ink.push_back(v == 1);
  return out;
}

// ---- replies ----

TEST(TerminalGraphics, KittyReplyWinsOverSixel) {
  EXPECT_EQ(parse_graphics_reply("\x1b_Gi=31;OK\x1b\\\x1b[?62;4;6;22c"), TerminalGraphics::Kitty);
  EXPECT_EQ(parse_graphics_reply("\x1b_Gi=31;OK\x1b\\\x1b[?62;c"), TerminalGraphics::Kitty);
}

TEST(TerminalGraphics, DeviceAttributesWithFourMeanSixel) {
  EXPECT_EQ(parse_graphics_reply("\x1b[?62;4;6;22c"), TerminalGraphics::Sixel);
  EXPECT_EQ(parse_graphics_reply("\x1b[?4c"), TerminalGraphics::Sixel);
  EXPECT_EQ(parse_graphics_reply("\x1b[?64;1;2;4c"), TerminalGraphics::Sixel);
}

TEST(TerminalGraphics, OtherAttributesMeanBraille) {
  EXPECT_EQ(parse_graphics_reply("\x1b[?62;1;6;22c"), TerminalGraphics::Braille);
  EXPECT_EQ(parse_graphics_reply("\x1b[?14;24;42c"), TerminalGraphics::Braille);  // 14, 24, 42 are not 4
  EXPECT_EQ(parse_graphics_reply("\x1b[?62;4"), TerminalGraphics::Braille);       // unfinished
  EXPECT_EQ(parse_graphics_reply(""), TerminalGraphics::Braille);
  EXPECT_EQ(parse_graphics_reply("4c"), TerminalGraphics::Braille);
}

TEST(TerminalGraphics, KittyErrorIsNotKitty) {
  EXPECT_EQ(parse_graphics_reply("\x1b_Gi=31;ENOTSUPPORTED:unsupported\x1b\\\x1b[?62;1c"),
            TerminalGraphics::Braille);
  EXPECT_EQ(parse_graphics_reply("\x1b_Gi=31;EINVAL:bad\x1b\\\x1b[?62;4c"), TerminalGraphics::Sixel);
  EXPECT_EQ(parse_graphics_reply("\x1b_Gi=7;OK\x1b\\\x1b[?62c"), TerminalGraphics::Braille);  // not our id
}

// ---- kitty ----

TEST(TerminalGraphics, KittyImageIsAPngOfTheAskedSize) {
  const std::string image = terminal_image(square(), kFrame, TerminalGraphics::Kitty, kWidth, kHeight);
  const std::string png = kitty_png(image);
  expect_png_size(png, kWidth, kHeight);
}

TEST(TerminalGraphics, KittySquareHasInkOnItsEdgesAndWhiteInside) {
  const Picture p =
      png_picture(kitty_png(terminal_image(square(), kFrame, TerminalGraphics::Kitty, kWidth, kHeight)));
  ASSERT_EQ(p.width, kWidth);
  ASSERT_EQ(p.height, kHeight);
  expect_square(p);
}

TEST(TerminalGraphics, KittyHiddenPiecesAreDashed) {
  std::vector<VisibleSegment> segments = square();
  segments.push_back(segment(-1, 0, 1, 0, true));
  const Picture p =
      png_picture(kitty_png(terminal_image(segments, kFrame, TerminalGraphics::Kitty, kWidth, kHeight)));
  ASSERT_EQ(p.width, kWidth);
  const int half = kHeight / 4;
  expect_dashed_row(p, kHeight / 2, kWidth / 2 - half + 2 * kSlackPx, kWidth / 2 + half - 2 * kSlackPx);
}

TEST(TerminalGraphics, LargeImagesAreChunkedAndBounded) {
  std::vector<VisibleSegment> fan;
  for (int k = 0; k < 200; ++k) fan.push_back(segment(0, 0, std::cos(k * 0.0314), std::sin(k * 0.0314)));
  const std::string image = terminal_image(fan, std::nullopt, TerminalGraphics::Kitty, 4000, 3000);
  EXPECT_GT(kitty_chunks(image).size(), 1u);
  expect_png_size(kitty_png(image), kMaxTerminalImageWidth, kMaxTerminalImageHeight);
}

TEST(TerminalGraphics, WithoutFrameTheSegmentsAreFitted) {
  // The same square, fitted to its own bounds: its edges are at the picture's border.
  const Picture p =
      png_picture(kitty_png(terminal_image(square(), std::nullopt, TerminalGraphics::Kitty, 100, 100)));
  ASSERT_EQ(p.width, 100);
  EXPECT_TRUE(p.ink_near(kSlackPx, 50));
  EXPECT_TRUE(p.ink_near(100 - 1 - kSlackPx, 50));
  EXPECT_FALSE(p.at(50, 50));
}

// ---- sixel ----

TEST(TerminalGraphics, SixelRasterAttributesGiveTheAskedSize) {
  const Sixel s = decode_sixel(terminal_image(square(), kFrame, TerminalGraphics::Sixel, kWidth, kHeight));
  EXPECT_EQ(s.raster_width, kWidth);
  EXPECT_EQ(s.raster_height, kHeight);
  for (int c : s.colour) ASSERT_NE(c, -1) << "every pixel is painted";
}

TEST(TerminalGraphics, SixelSquareHasInkOnItsEdgesAndWhiteInside) {
  const Sixel s = decode_sixel(terminal_image(square(), kFrame, TerminalGraphics::Sixel, kWidth, kHeight));
  ASSERT_EQ(s.picture.width, kWidth);
  ASSERT_EQ(s.picture.height, kHeight);
  expect_square(s.picture);
}

TEST(TerminalGraphics, SixelHiddenPiecesAreDashed) {
  std::vector<VisibleSegment> segments = square();
  segments.push_back(segment(-1, 0, 1, 0, true));
  const Sixel s = decode_sixel(terminal_image(segments, kFrame, TerminalGraphics::Sixel, kWidth, kHeight));
  ASSERT_EQ(s.picture.width, kWidth);
  const int half = kHeight / 4;
  expect_dashed_row(s.picture, kHeight / 2, kWidth / 2 - half + 2 * kSlackPx,
                    kWidth / 2 + half - 2 * kSlackPx);
}

TEST(TerminalGraphics, SixelHeightNotAMultipleOfSix) {
  const Sixel s = decode_sixel(terminal_image(square(), kFrame, TerminalGraphics::Sixel, 61, 47));
  EXPECT_EQ(s.raster_width, 61);
  EXPECT_EQ(s.raster_height, 47);
  for (int c : s.colour) ASSERT_NE(c, -1);
  expect_square(s.picture);
}

TEST(TerminalGraphics, BrailleIsTheBraillePicture) {
  EXPECT_EQ(terminal_image(square(), kFrame, TerminalGraphics::Braille, kWidth, kHeight),
            braille_picture(square(), kFrame, kWidth / kAssumedCellWidthPx, kHeight / kAssumedCellHeightPx));
}

TEST(TerminalGraphics, EmptyDrawingIsBlank) {
  const Sixel s = decode_sixel(terminal_image({}, std::nullopt, TerminalGraphics::Sixel, 30, 20));
  for (bool ink : s.picture.ink) ASSERT_FALSE(ink);
  const Picture p = png_picture(kitty_png(terminal_image({}, std::nullopt, TerminalGraphics::Kitty, 30, 20)));
  for (bool ink : p.ink) ASSERT_FALSE(ink);
}

// ---- detection without a terminal ----

class EnvGuard {
 public:
  explicit EnvGuard(const char* name) : name_(name) {
    if (const char* v = std::getenv(name)) saved_ = v;
  }
  ~EnvGuard() {
    if (saved_)
      ::setenv(name_, saved_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

struct Pipe {
  int fds[2] = {-1, -1};
  Pipe() { EXPECT_EQ(::pipe(fds), 0); }
  ~Pipe() {
    ::close(fds[0]);
    ::close(fds[1]);
  }
};

TEST(TerminalGraphics, EnvironmentOverridesDetection) {
  const EnvGuard guard("HLRSCRIPT_GRAPHICS");
  const Pipe p;
  ::setenv("HLRSCRIPT_GRAPHICS", "kitty", 1);
  EXPECT_EQ(detect_terminal_graphics(p.fds[0], p.fds[1]), TerminalGraphics::Kitty);
  ::setenv("HLRSCRIPT_GRAPHICS", "sixel", 1);
  EXPECT_EQ(detect_terminal_graphics(p.fds[0], p.fds[1]), TerminalGraphics::Sixel);
  ::setenv("HLRSCRIPT_GRAPHICS", "braille", 1);
  EXPECT_EQ(detect_terminal_graphics(p.fds[0], p.fds[1]), TerminalGraphics::Braille);
  ::setenv("HLRSCRIPT_GRAPHICS", "iterm", 1);  // ignored: not a tty, so braille
  EXPECT_EQ(detect_terminal_graphics(p.fds[0], p.fds[1]), TerminalGraphics::Braille);
  ::unsetenv("HLRSCRIPT_GRAPHICS");
  EXPECT_EQ(detect_terminal_graphics(p.fds[0], p.fds[1]), TerminalGraphics::Braille);
}

// A pseudo-terminal whose "terminal" side has already typed its reply: detection reads it, whatever
// the timing, and the tty's modes are as they were afterwards.
class FakeTerminal {
 public:
  FakeTerminal() {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) return;
    slave_ = ::open(::ptsname(master_), O_RDWR | O_NOCTTY);
  }
  ~FakeTerminal() {
    if (slave_ >= 0) ::close(slave_);
    if (master_ >= 0) ::close(master_);
  }
  bool ok() const { return slave_ >= 0; }
  int tty() const { return slave_; }
  void answer(const std::string& reply) const {
    ASSERT_EQ(::write(master_, reply.data(), reply.size()), static_cast<ssize_t>(reply.size()));
  }
  // What the program wrote to the terminal (the queries), without waiting.
  std::string written() const {
    std::string out;
    char buffer[256];
    const int flags = ::fcntl(master_, F_GETFL);
    ::fcntl(master_, F_SETFL, flags | O_NONBLOCK);
    for (ssize_t n; (n = ::read(master_, buffer, sizeof buffer)) > 0;)
      out.append(buffer, static_cast<std::size_t>(n));
    ::fcntl(master_, F_SETFL, flags);
    return out;
  }

 private:
  int master_ = -1, slave_ = -1;
};

TerminalGraphics detect_with_reply(const std::string& reply, std::string* written = nullptr) {
  const EnvGuard graphics("HLRSCRIPT_GRAPHICS"), term("TERM"), tmux("TMUX");
  ::unsetenv("HLRSCRIPT_GRAPHICS");
  ::unsetenv("TMUX");
  ::setenv("TERM", "xterm-256color", 1);
  const FakeTerminal t;
  if (!t.ok()) return TerminalGraphics::Braille;
  termios before{};
  EXPECT_EQ(::tcgetattr(t.tty(), &before), 0);
  t.answer(reply);
  const TerminalGraphics kind = detect_terminal_graphics(t.tty(), t.tty());
  termios after{};
  EXPECT_EQ(::tcgetattr(t.tty(), &after), 0);
  EXPECT_EQ(after.c_lflag, before.c_lflag) << "terminal modes restored";
  EXPECT_EQ(after.c_cc[VMIN], before.c_cc[VMIN]);
  if (written) *written = t.written();
  return kind;
}

TEST(TerminalGraphics, DetectionAsksTheTerminal) {
  ASSERT_TRUE(FakeTerminal().ok())
      << "no pseudo-terminal could be opened (posix_openpt): the detection needs one";
  std::string written;
  EXPECT_EQ(detect_with_reply("\x1b_Gi=31;OK\x1b\\\x1b[?62;22c", &written), TerminalGraphics::Kitty);
  EXPECT_NE(written.find("\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\\x1b[c"), std::string::npos);
  EXPECT_EQ(detect_with_reply("\x1b[?62;4;22c"), TerminalGraphics::Sixel);
  EXPECT_EQ(detect_with_reply("\x1b[?1;2c"), TerminalGraphics::Braille);
  EXPECT_EQ(detect_with_reply("\x1b_Gi=31;OK\x1b\\"), TerminalGraphics::Kitty);  // no DA1: after the wait
  EXPECT_EQ(detect_with_reply(""), TerminalGraphics::Braille);                   // silence
}

TEST(TerminalGraphics, InsideTmuxDetectionIsBraille) {
  const EnvGuard graphics("HLRSCRIPT_GRAPHICS"), term("TERM"), tmux("TMUX");
  ::unsetenv("HLRSCRIPT_GRAPHICS");
  ::unsetenv("TMUX");
  const FakeTerminal t;
  ASSERT_TRUE(t.ok()) << "no pseudo-terminal could be opened (posix_openpt): the detection needs one";
  ::setenv("TERM", "tmux-256color", 1);
  EXPECT_EQ(detect_terminal_graphics(t.tty(), t.tty()), TerminalGraphics::Braille);
  ::setenv("TERM", "screen", 1);
  EXPECT_EQ(detect_terminal_graphics(t.tty(), t.tty()), TerminalGraphics::Braille);
  ::setenv("TERM", "xterm", 1);
  ::setenv("TMUX", "/tmp/tmux-1000/default,1,0", 1);
  EXPECT_EQ(detect_terminal_graphics(t.tty(), t.tty()), TerminalGraphics::Braille);
  EXPECT_EQ(t.written(), "") << "nothing asked";
  ::setenv("HLRSCRIPT_GRAPHICS", "kitty", 1);  // the override still wins
  EXPECT_EQ(detect_terminal_graphics(t.tty(), t.tty()), TerminalGraphics::Kitty);
}

TEST(TerminalGraphics, PixelsFromTheTty) {
  const FakeTerminal t;
  ASSERT_TRUE(t.ok()) << "no pseudo-terminal could be opened (posix_openpt): the detection needs one";
  winsize ws{};
  ws.ws_col = 100;
  ws.ws_row = 30;
  ws.ws_xpixel = 1000;
  ws.ws_ypixel = 600;
  ASSERT_EQ(::ioctl(t.tty(), TIOCSWINSZ, &ws), 0);
  const PixelSize size = terminal_pixels(t.tty(), 100, 30);
  EXPECT_EQ(size.width, 1000);
  EXPECT_EQ(size.height, 600 - kTextRowsBelowPicture * (600 / 30));
  ws.ws_xpixel = ws.ws_ypixel = 0;  // a terminal that does not say: the assumed cells
  ASSERT_EQ(::ioctl(t.tty(), TIOCSWINSZ, &ws), 0);
  EXPECT_EQ(terminal_pixels(t.tty(), 100, 30).width, 100 * kAssumedCellWidthPx);
}

TEST(TerminalGraphics, PixelsWithoutATtyAssumeTheCellSize) {
  const Pipe p;
  const PixelSize size = terminal_pixels(p.fds[0], 80, 24);
  EXPECT_EQ(size.width, 80 * kAssumedCellWidthPx);
  EXPECT_EQ(size.height, (24 - kTextRowsBelowPicture) * kAssumedCellHeightPx);
  const PixelSize tiny = terminal_pixels(p.fds[0], 0, 1);
  EXPECT_GE(tiny.width, 1);
  EXPECT_GE(tiny.height, 1);
}

}  // namespace
}  // namespace hlr::runtime
