#include "core/plan/hidden_precedence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "core/geometry/rect2.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// Who covers whom: a piece of rank r covers the hidden pieces of higher rank (visible 0, hidden its level).
int rank_of(const PlotPiece& p) { return p.layer == StrokeLayer::Visible ? 0 : std::max(p.level, 1); }

}  // namespace

std::size_t drop_hidden_under_visible(std::vector<PlotPiece>& pieces) {
  const double tol = Tolerance::kCoincidentLineMm;
  Rect2 box = Rect2::none();
  std::size_t hidden = 0;
  for (const PlotPiece& p : pieces) {
    if (p.layer == StrokeLayer::Hatch) continue;
    box.include(p.a);
    box.include(p.b);
    hidden += p.layer == StrokeLayer::Hidden;
  }
  if (hidden == 0 || box.empty()) return 0;

  // A grid of cells about a piece long; each coverer is entered in the cells of points along it no more
  // than half a cell apart, so a hidden piece meeting it shares a cell, or a neighbouring one, with it.
  const double side = std::max({box.width(), box.height(), 1.0});
  const double cell = side / std::clamp(std::sqrt(static_cast<double>(pieces.size())), 1.0, 4096.0);
  const auto key = [&](long long i, long long j) { return (i << 32) ^ (j & 0xffffffffLL); };
  const auto cell_of = [&](Point2 p) {
    return std::pair<long long, long long>{static_cast<long long>(std::floor((p.x - box.xmin) / cell)),
                                           static_cast<long long>(std::floor((p.y - box.ymin) / cell))};
  };
  // The cells of points along a→b every half cell (consecutive repeats skipped).
  const auto cells_along = [&](const PlotPiece& p, auto&& visit) {
    const double len = distance(p.a, p.b);
    const int steps = static_cast<int>(std::ceil(2 * len / cell)) + 1;
    long long last_i = -1LL << 40, last_j = 0;
    for (int s = 0; s <= steps; ++s) {
      const auto [i, j] = cell_of(lerp(p.a, p.b, static_cast<double>(s) / steps));
      if (i == last_i && j == last_j) continue;
      last_i = i;
      last_j = j;
      visit(i, j);
    }
  };
  std::unordered_map<long long, std::vector<std::uint32_t>> grid;
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    const PlotPiece& p = pieces[k];
    if (p.layer == StrokeLayer::Hatch) continue;
    cells_along(p, [&](long long i, long long j) {
      std::vector<std::uint32_t>& c = grid[key(i, j)];
      if (c.empty() || c.back() != k) c.push_back(k);
    });
  }

  std::vector<PlotPiece> out;
  out.reserve(pieces.size());
  std::vector<std::uint32_t> seen;
  std::vector<std::pair<double, double>> spans;
  std::size_t changed = 0;
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    const PlotPiece& h = pieces[k];
    const double len = distance(h.a, h.b);
    if (h.layer != StrokeLayer::Hidden || len <= tol) {
      out.push_back(h);
      continue;
    }
    const Vector2 u = (1 / len) * (h.b - h.a);
    const int rank = rank_of(h);
    seen.clear();
    spans.clear();
    cells_along(h, [&](long long i, long long j) {
      for (long long di = -1; di <= 1; ++di)
        for (long long dj = -1; dj <= 1; ++dj) {
          const auto it = grid.find(key(i + di, j + dj));
          if (it == grid.end()) continue;
          for (const std::uint32_t m : it->second) {
            const PlotPiece& c = pieces[m];
            // Shallower pieces cover it, and so do earlier hidden pieces of its own level (a dashed line
            // drawn once, not once for each face behind).
            const int cover_rank = rank_of(c);
            if (m == k || cover_rank > rank ||
                (cover_rank == rank && (m > k || c.layer != StrokeLayer::Hidden)) ||
                std::find(seen.begin(), seen.end(), m) != seen.end())
              continue;
            seen.push_back(m);
            // On one line: both ends of the coverer within the tolerance of the hidden piece's line, or (a
            // coverer longer than it) both ends of the hidden piece within it of the coverer's.
            const double ta = dot(c.a - h.a, u), tb = dot(c.b - h.a, u);
            const bool on_hidden =
                std::abs(cross(u, c.a - h.a)) <= tol && std::abs(cross(u, c.b - h.a)) <= tol;
            bool on_cover = false;
            if (!on_hidden) {
              const double clen = distance(c.a, c.b);
              if (clen <= len) continue;
              const Vector2 v = (1 / clen) * (c.b - c.a);
              on_cover = std::abs(cross(v, h.a - c.a)) <= tol && std::abs(cross(v, h.b - c.a)) <= tol;
            }
            if (!on_hidden && !on_cover) continue;
            const double lo = std::max(std::min(ta, tb), 0.0), hi = std::min(std::max(ta, tb), len);
            if (hi > lo) spans.emplace_back(lo, hi);
          }
        }
    });
    if (spans.empty()) {
      out.push_back(h);
      continue;
    }
    std::sort(spans.begin(), spans.end());
    // What no span covers, each part longer than the tolerance.
    double from = 0;
    bool cut = false;
    const auto keep = [&](double a, double b) {
      if (b - a <= tol) return;
      PlotPiece part = h;
      part.a = a == 0 ? h.a : h.a + a * u;
      part.b = b == len ? h.b : h.a + b * u;
      out.push_back(part);
    };
    for (const auto& [a, b] : spans) {
      if (a > from) keep(from, a);
      if (b > from) from = b;
      cut = true;
    }
    if (from < len) keep(from, len);
    changed += cut;
  }
  pieces = std::move(out);
  return changed;
}

}  // namespace hlr
