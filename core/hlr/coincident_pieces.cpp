#include "core/hlr/coincident_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "core/geometry/rect2.hpp"
#include "core/parallel.hpp"
#include "core/release_memory.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// Position of q along a→b (0 at a, 1 at b) and its distance from that line.
struct Along {
  double t, off;
};
Along along(Point3 a, Point3 b, Point3 q) {
  const Vector3 d = b - a;
  const double len2 = dot(d, d);
  if (len2 <= 0) return {0, distance(a, q)};
  const double t = dot(q - a, d) / len2;
  return {t, distance(q, a + t * d)};
}

}  // namespace

std::size_t remove_covered_pieces(std::vector<VisibleSegment>& segments, unsigned threads) {
  const std::size_t n = segments.size();
  if (n < 2) return 0;
  double world = 0, picture = 0;
  Rect2 box = Rect2::none();  // of the visible pieces' pictures
  std::size_t count = 0;
  for (const VisibleSegment& s : segments) {
    for (Point3 p : {s.p0, s.p1}) world = std::max({world, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    for (Point2 p : {s.s0, s.s1}) picture = std::max({picture, std::abs(p.x), std::abs(p.y)});
    if (s.hidden) continue;
    box.include(s.s0);
    box.include(s.s1);
    ++count;
  }
  if (count < 2) return 0;
  const double wtol = Tolerance::for_extent(world).length;
  const double ptol = Tolerance::for_extent(picture).length;

  // A grid over the picture, each visible piece entered in the cells its line passes through (cells about
  // one piece long, so a cell holds a few): pieces on one line share cells along it.
  const double side = std::max({box.width(), box.height(), ptol, Tolerance::kFloor});
  const int cells = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(count))), 1, 2048);
  const double cell = side / cells;  // cell_of clamps the far border into the last cell
  const double grow = 2 * ptol;      // a piece is entered in every cell its line comes within this of
  auto cell_of = [&](double v, double lo) {
    return std::clamp(static_cast<int>(std::floor((v - lo) / cell)), 0, cells - 1);
  };
  // Cells a piece passes through: along its longer axis, for each column (or row) the range its line
  // covers there, widened by `grow`.
  auto for_each_cell = [&](const VisibleSegment& s, auto&& visit) {
    const Point2 a = s.s0, b = s.s1;
    const bool along_x = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
    const double a_major = along_x ? a.x : a.y, b_major = along_x ? b.x : b.y;
    const double a_minor = along_x ? a.y : a.x, b_minor = along_x ? b.y : b.x;
    const double major_lo = along_x ? box.xmin : box.ymin, minor_lo = along_x ? box.ymin : box.xmin;
    const double lo = std::min(a_major, b_major), hi = std::max(a_major, b_major);
    const double slope = b_major != a_major ? (b_minor - a_minor) / (b_major - a_major) : 0;
    // The line's minor coordinate at major coordinate m, m clamped to the piece.
    auto minor_at = [&](double m) { return a_minor + slope * (std::clamp(m, lo, hi) - a_major); };
    for (int i = cell_of(lo - grow, major_lo); i <= cell_of(hi + grow, major_lo); ++i) {
      const double v0 = minor_at(major_lo + i * cell), v1 = minor_at(major_lo + (i + 1) * cell);
      for (int j = cell_of(std::min(v0, v1) - grow, minor_lo);
           j <= cell_of(std::max(v0, v1) + grow, minor_lo); ++j)
        visit(along_x ? i + j * cells : j + i * cells);
    }
  };
  // Each piece's cells, found once (CSR: piece_cells[cell_start[i] .. cell_start[i + 1])), then the
  // pieces of each cell, in result order, by a counting sort.
  // Found by chunks of pieces in parallel and joined in piece order.
  constexpr std::uint32_t kChunk = 1024;
  const std::uint32_t chunks = (static_cast<std::uint32_t>(n) + kChunk - 1) / kChunk;
  const unsigned setup_threads = threads_for(n, 20000, threads);
  std::vector<std::uint32_t> cell_start(n + 1, 0);
  std::vector<std::vector<std::uint32_t>> chunk_cells(chunks);
  parallel_chunks(chunks, setup_threads, [&](std::size_t k) {
    const auto first = static_cast<std::uint32_t>(k) * kChunk;
    const std::uint32_t last = std::min(static_cast<std::uint32_t>(n), first + kChunk);
    std::vector<std::uint32_t> cells;  // moved in once: the chunks' lists share cache lines
    for (std::uint32_t i = first; i < last; ++i) {
      const std::size_t before = cells.size();
      if (!segments[i].hidden)
        for_each_cell(segments[i], [&](int c) { cells.push_back(static_cast<std::uint32_t>(c)); });
      cell_start[i + 1] = static_cast<std::uint32_t>(cells.size() - before);
    }
    chunk_cells[k] = std::move(cells);
  });
  for (std::size_t i = 0; i < n; ++i) cell_start[i + 1] += cell_start[i];
  std::vector<std::uint32_t> piece_cells;
  piece_cells.reserve(cell_start[n]);
  for (std::vector<std::uint32_t>& cells_of_chunk : chunk_cells) {
    piece_cells.insert(piece_cells.end(), cells_of_chunk.begin(), cells_of_chunk.end());
    release(cells_of_chunk);
  }
  std::vector<std::uint32_t> starts(static_cast<std::size_t>(cells) * cells + 1, 0);
  for (std::uint32_t c : piece_cells) ++starts[c + 1];
  for (std::size_t c = 1; c < starts.size(); ++c) starts[c] += starts[c - 1];
  std::vector<std::uint32_t> members(piece_cells.size());
  {
    std::vector<std::uint32_t> fill(starts.begin(), starts.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t k = cell_start[i]; k < cell_start[i + 1]; ++k) members[fill[piece_cells[k]]++] = i;
  }

  // Per piece its picture line (a point and the unit direction), for a quick test of the picture first.
  struct PictureLine {
    Point2 a;
    Vector2 u;
  };
  std::vector<PictureLine> lines(n);
  parallel_chunks(chunks, setup_threads, [&](std::size_t k) {
    const auto first = static_cast<std::uint32_t>(k) * kChunk;
    for (std::uint32_t i = first; i < std::min(static_cast<std::uint32_t>(n), first + kChunk); ++i) {
      const Vector2 d = segments[i].s1 - segments[i].s0;
      const double len = length(d);
      lines[i] = {segments[i].s0, len > 0 ? (1 / len) * d : Vector2{0, 0}};
    }
  });
  auto on_line = [&](std::uint32_t i, std::uint32_t j, std::pair<double, double>& span) {
    const PictureLine& l = lines[i];
    const VisibleSegment& o = segments[j];
    if (std::abs(cross(l.u, o.s0 - l.a)) > ptol || std::abs(cross(l.u, o.s1 - l.a)) > ptol) return false;
    const VisibleSegment& s = segments[i];
    const Along a0 = along(s.p0, s.p1, o.p0), a1 = along(s.p0, s.p1, o.p1);
    if (a0.off > wtol || a1.off > wtol) return false;
    span = {std::min(a0.t, a1.t), std::max(a0.t, a1.t)};
    return span.second > 0 && span.first < 1;
  };

  // A piece covered wholly has its middle covered: by an earlier piece on its line whose picture passes
  // within `near` of the middle's — the tolerance, and the slack along the piece seen in the picture
  // (widened 16 times for perspective) — so through a cell meeting the square of that half-width around
  // it: nearly always the middle's own cell alone (the tall sides of a 20 000-gon prism put some fifty
  // pieces in each cell, and the eight neighbours cost a fifth of its frame). Asked first, this keeps the
  // full search (every earlier piece in every cell the piece crosses: many, for long pieces in crowded
  // parts of the picture) to the few pieces that are covered.
  auto middle_covered = [&](std::uint32_t i, double slack) {
    const Point2 mid = lerp(segments[i].s0, segments[i].s1, 0.5);
    const double near = grow + 16 * slack * distance(segments[i].s0, segments[i].s1);
    const int x0 = cell_of(mid.x - near, box.xmin), x1 = cell_of(mid.x + near, box.xmin);
    const int y0 = cell_of(mid.y - near, box.ymin), y1 = cell_of(mid.y + near, box.ymin);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const std::size_t c = static_cast<std::size_t>(x) + static_cast<std::size_t>(y) * cells;
        for (std::uint32_t m = starts[c]; m < starts[c + 1]; ++m) {
          const std::uint32_t j = members[m];
          if (j >= i) break;
          std::pair<double, double> span;
          if (on_line(i, j, span) && span.first <= 0.5 + slack && span.second >= 0.5 - slack) return true;
        }
      }
    return false;
  };

  // Each piece is decided on its own (in parallel): covered wholly when the spans, along it, of the
  // earlier pieces on its line join up from 0 to 1 with no gap longer than the tolerance.
  std::vector<char> remove(n, 0);
  parallel_chunks(chunks, setup_threads, [&](std::size_t k) {
    std::vector<std::uint32_t> met;
    std::vector<std::pair<double, double>> spans;
    const auto first = static_cast<std::uint32_t>(k) * kChunk;
    const std::uint32_t last = std::min(static_cast<std::uint32_t>(n), first + kChunk);
    for (std::uint32_t i = first; i < last; ++i) {
      if (segments[i].hidden) continue;
      const double len = distance(segments[i].p0, segments[i].p1);
      const double slack = len > 0 ? wtol / len : 1;
      if (!middle_covered(i, slack)) continue;
      met.clear();
      spans.clear();
      for (std::uint32_t k = cell_start[i]; k < cell_start[i + 1]; ++k) {
        const std::uint32_t c = piece_cells[k];
        for (std::uint32_t m = starts[c]; m < starts[c + 1]; ++m) {
          const std::uint32_t j = members[m];
          if (j >= i) break;  // members are in result order: only earlier pieces can cover this one
          if (std::find(met.begin(), met.end(), j) != met.end()) continue;
          met.push_back(j);
          std::pair<double, double> span;
          if (on_line(i, j, span)) spans.push_back(span);
        }
      }
      if (spans.empty()) continue;
      std::sort(spans.begin(), spans.end());
      double reach = 0;
      for (const auto& [a, b] : spans) {
        if (a > reach + slack) break;
        reach = std::max(reach, b);
      }
      remove[i] = reach >= 1 - slack;
    }
  });
  std::size_t removed = 0;
  for (char r : remove) removed += r != 0;
  if (removed == 0) return 0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!remove[i]) segments[kept++] = segments[i];
  segments.resize(kept);
  return removed;
}

}  // namespace hlr
