#include "core/plan/plotter_stepping.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace hlr {

std::string plotter_steps(GridPoint a, GridPoint b, bool knights_move_correction) {
  const std::int64_t a0 = b.x - a.x, b0 = b.y - a.y;
  const bool B = a0 > 0, C = b0 > 0, K = std::llabs(a0) - std::llabs(b0) > 0;
  const char d_move = B ? (C ? '2' : '4') : (C ? '8' : '6');
  const char s_move = K ? (B ? '3' : '7') : (C ? '1' : '5');
  const std::int64_t w0 = std::llabs(std::llabs(a0) - std::llabs(b0));
  const std::int64_t v0 = std::min(std::llabs(a0), std::llabs(b0));
  const std::int64_t moves = std::max(std::llabs(a0), std::llabs(b0));
  std::string out;
  out.reserve(static_cast<std::size_t>(moves));
  std::int64_t delta = 0;
  for (std::int64_t i = 0; i < moves; ++i) {
    const std::int64_t ds = delta + v0, dd = delta - w0;
    const std::int64_t as = std::llabs(ds), ad = std::llabs(dd);
    const bool straight = as < ad || (as == ad && knights_move_correction && !B);
    out.push_back(straight ? s_move : d_move);
    delta = straight ? ds : dd;
  }
  return out;
}

GridPoint apply_plotter_steps(GridPoint a, std::string_view steps) {
  static constexpr int dx[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  static constexpr int dy[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  for (char c : steps) {
    if (c < '1' || c > '8') throw std::invalid_argument("apply_plotter_steps: direction codes are 1-8");
    a.x += dx[c - '1'];
    a.y += dy[c - '1'];
  }
  return a;
}

char opposite_plotter_step(char code) {
  if (code < '1' || code > '8') throw std::invalid_argument("opposite_plotter_step: direction codes are 1-8");
  return static_cast<char>('1' + (code - '1' + 4) % 8);
}

}  // namespace hlr
