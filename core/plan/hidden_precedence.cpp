#include "core/plan/hidden_precedence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <utility>

#include "core/tolerance.hpp"

namespace hlr {
namespace {

// Who covers whom: a piece of rank r covers the hidden pieces of higher rank (visible 0, hidden its level).
int rank_of(const PlotPiece& p) { return p.layer == StrokeLayer::Visible ? 0 : std::max(p.level, 1); }

// Pieces are found by the line they lie on: its direction θ in [0, π) and its signed distance ρ from the
// page's origin, in buckets of kAngleBucket radians and kOffsetBucketMm; a hidden piece looks in its own
// bucket and those beside it. Lines that coincide on the page (an orthographic view's edges, one behind
// another) fall in one bucket or the next; pieces only within the tolerance of one another's line at a
// slant may be missed, and are then drawn both (never dropped wrongly: the test below decides).
constexpr double kAngleBucket = 0.01;
constexpr double kOffsetBucketMm = 0.05;
const int kAngleBuckets = static_cast<int>(std::ceil(std::numbers::pi / kAngleBucket));

struct LineKey {
  int angle;
  long long offset;
};

LineKey line_key(const PlotPiece& p) {
  double angle = std::atan2(p.b.y - p.a.y, p.b.x - p.a.x);
  if (angle < 0) angle += std::numbers::pi;
  if (angle >= std::numbers::pi) angle -= std::numbers::pi;
  const double rho = -std::sin(angle) * p.a.x + std::cos(angle) * p.a.y;
  return {std::min(static_cast<int>(angle / kAngleBucket), kAngleBuckets - 1),
          static_cast<long long>(std::floor(rho / kOffsetBucketMm))};
}

long long bucket(int angle, long long offset) { return (offset << 12) ^ angle; }

}  // namespace

std::size_t drop_hidden_under_visible(std::vector<PlotPiece>& pieces) {
  const double tol = Tolerance::kCoincidentLineMm;
  std::size_t hidden = 0;
  for (const PlotPiece& p : pieces) hidden += p.layer == StrokeLayer::Hidden;
  if (hidden == 0) return 0;

  std::unordered_map<long long, std::vector<std::uint32_t>> lines;
  std::vector<LineKey> keys(pieces.size());
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    if (pieces[k].layer == StrokeLayer::Hatch) continue;
    keys[k] = line_key(pieces[k]);
    lines[bucket(keys[k].angle, keys[k].offset)].push_back(k);
  }

  std::vector<PlotPiece> out;
  out.reserve(pieces.size());
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
    spans.clear();
    const auto visit = [&](const std::vector<std::uint32_t>& members) {
      for (const std::uint32_t m : members) {
        const PlotPiece& c = pieces[m];
        // Shallower pieces cover it, and so do earlier hidden pieces of its own level (a dashed line drawn
        // once, not once for each face behind).
        const int cover_rank = rank_of(c);
        if (m == k || cover_rank > rank || (cover_rank == rank && (m > k || c.layer != StrokeLayer::Hidden)))
          continue;
        // On one line: both ends of the coverer within the tolerance of the hidden piece's line, or (a
        // coverer longer than it) both ends of the hidden piece within it of the coverer's.
        bool on_line = std::abs(cross(u, c.a - h.a)) <= tol && std::abs(cross(u, c.b - h.a)) <= tol;
        if (!on_line) {
          const double clen = distance(c.a, c.b);
          if (clen <= len) continue;
          const Vector2 v = (1 / clen) * (c.b - c.a);
          on_line = std::abs(cross(v, h.a - c.a)) <= tol && std::abs(cross(v, h.b - c.a)) <= tol;
        }
        if (!on_line) continue;
        const double ta = dot(c.a - h.a, u), tb = dot(c.b - h.a, u);
        const double lo = std::max(std::min(ta, tb), 0.0), hi = std::min(std::max(ta, tb), len);
        if (hi > lo) spans.emplace_back(lo, hi);
      }
    };
    const LineKey key = keys[k];
    for (int da = -1; da <= 1; ++da) {
      int angle = key.angle + da;
      // Past either end of the half turn the line's direction flips, and so does the sign of its offset.
      const bool flipped = angle < 0 || angle >= kAngleBuckets;
      angle = (angle + kAngleBuckets) % kAngleBuckets;
      for (long long dr = -1; dr <= 1; ++dr) {
        const long long offset = flipped ? -key.offset - 1 + dr : key.offset + dr;
        if (const auto it = lines.find(bucket(angle, offset)); it != lines.end()) visit(it->second);
      }
    }
    if (spans.empty()) {
      out.push_back(h);
      continue;
    }
    std::sort(spans.begin(), spans.end());
    // What no span covers, each part longer than the tolerance.
    const auto keep = [&](double a, double b) {
      if (b - a <= tol) return;
      PlotPiece part = h;
      part.a = a == 0 ? h.a : h.a + a * u;
      part.b = b == len ? h.b : h.a + b * u;
      out.push_back(part);
    };
    double from = 0;
    for (const auto& [a, b] : spans) {
      if (a > from) keep(from, a);
      from = std::max(from, b);
    }
    if (from < len) keep(from, len);
    ++changed;
  }
  pieces = std::move(out);
  return changed;
}

}  // namespace hlr
