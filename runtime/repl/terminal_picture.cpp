#include "runtime/repl/terminal_picture.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/tolerance.hpp"

namespace hlr::runtime {

TerminalSize terminal_size(int fd) {
  TerminalSize size;
  winsize ws{};
  if (::ioctl(fd, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 && ws.ws_row > 0) {
    size.columns = ws.ws_col;
    size.rows = ws.ws_row;
    return size;
  }
  if (const char* c = std::getenv("COLUMNS")) size.columns = std::max(1, std::atoi(c));
  if (const char* r = std::getenv("LINES")) size.rows = std::max(1, std::atoi(r));
  return size;
}

namespace {

// The bit of dot (x, y) within its cell (x 0–1, y 0–3), in the order Unicode numbers braille dots.
constexpr std::uint8_t kDotBit[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};

void put_utf8(std::string& out, unsigned cp) {
  out += static_cast<char>(0xe0 | (cp >> 12));
  out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
  out += static_cast<char>(0x80 | (cp & 0x3f));
}

}  // namespace

PictureFit fit_picture(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                       double width, double height) {
  PictureFit fit;
  if (frame && !frame->empty()) {
    fit.box = *frame;
  } else {
    for (const VisibleSegment& s : segments) {
      fit.box.include(s.s0);
      fit.box.include(s.s1);
    }
  }
  if (fit.box.empty()) return fit;
  const double bw = std::max(fit.box.width(), Tolerance::kFloor),
               bh = std::max(fit.box.height(), Tolerance::kFloor);
  fit.scale = std::min(width / bw, height / bh);
  fit.ox = (width - fit.scale * bw) / 2;
  fit.oy = (height - fit.scale * bh) / 2;
  return fit;
}

std::string braille_picture(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                            int columns, int rows) {
  columns = std::clamp(columns, 1, 1000);
  rows = std::clamp(rows, 1, 1000);
  const int width = 2 * columns, height = 4 * rows;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);

  // Dot centres run from 0 to width − 1: the picture fits that span.
  const PictureFit fit = fit_picture(segments, frame, width - 1, height - 1);
  if (!fit.box.empty()) {
    const double scale = fit.scale;
    auto dot = [&](double x, double y) {  // picture (x right, y up) → a dot, y down
      const Point2 at = fit.map({x, y});
      const long dx = std::lround(at.x), dy = std::lround(at.y);
      if (dx < 0 || dy < 0 || dx >= width || dy >= height) return;
      cells[static_cast<std::size_t>(dy / 4) * static_cast<std::size_t>(columns) +
            static_cast<std::size_t>(dx / 2)] |= kDotBit[dy % 4][dx % 2];
    };
    for (const VisibleSegment& s : segments) {
      const double len = std::max(std::abs(s.s1.x - s.s0.x), std::abs(s.s1.y - s.s0.y)) * scale;
      if (!std::isfinite(len)) continue;
      const int steps = std::clamp(static_cast<int>(std::ceil(len)), 1, 4 * (width + height));
      for (int k = 0; k <= steps; ++k) {
        if (s.hidden && k % 2) continue;
        const double t = static_cast<double>(k) / steps;
        dot(s.s0.x + t * (s.s1.x - s.s0.x), s.s0.y + t * (s.s1.y - s.s0.y));
      }
    }
  }
  std::string out;
  out.reserve(cells.size() * 3 + static_cast<std::size_t>(rows));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c)
      put_utf8(out, 0x2800u + cells[static_cast<std::size_t>(r * columns + c)]);
    out += '\n';
  }
  return out;
}

}  // namespace hlr::runtime
