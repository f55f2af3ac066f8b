// order_exact(): Held–Karp over (strokes, entry choice) for small groups (core/plan/stroke_order.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/plan/stroke_order.hpp"

namespace hlr::plan {
namespace {

constexpr std::uint32_t kNone = ~0u;

Pt at(const std::vector<GridPoint>& vertices, std::uint32_t v) {
  return {static_cast<double>(vertices[v].x), static_cast<double>(vertices[v].y)};
}

}  // namespace

bool order_exact(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                 const TourEnds& ends) {
  const std::size_t n = strokes.size();
  if (n > kExactOrderStrokes) return false;
  // Choices: (stroke, entry vertex index, exit vertex index).
  struct Choice {
    std::uint32_t stroke, entry, exit;
    Pt in, out;
  };
  std::vector<Choice> choices;
  for (std::uint32_t s = 0; s < n; ++s) {
    const std::vector<std::uint32_t>& v = strokes[s].vertices;
    const std::uint32_t last = static_cast<std::uint32_t>(v.size() - 1);
    if (strokes[s].closed) {
      for (std::uint32_t k = 0; k < last; ++k)
        choices.push_back({s, k, k, at(vertices, v[k]), at(vertices, v[k])});
    } else {
      choices.push_back({s, 0, last, at(vertices, v[0]), at(vertices, v[last])});
      choices.push_back({s, last, 0, at(vertices, v[last]), at(vertices, v[0])});
    }
    if (choices.size() > kExactOrderChoices) return false;
  }
  if (n == 0) return true;
  const std::size_t C = choices.size(), full = (std::size_t{1} << n) - 1;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dp((full + 1) * C, inf);
  std::vector<std::uint32_t> parent((full + 1) * C, kNone);
  for (std::size_t c = 0; c < C; ++c)
    dp[(std::size_t{1} << choices[c].stroke) * C + c] = dist(ends.start, choices[c].in);
  for (std::size_t mask = 1; mask <= full; ++mask)
    for (std::size_t c = 0; c < C; ++c) {
      const double base = dp[mask * C + c];
      if (base == inf) continue;
      for (std::size_t c2 = 0; c2 < C; ++c2) {
        const std::size_t bit = std::size_t{1} << choices[c2].stroke;
        if (mask & bit) continue;
        const double v = base + dist(choices[c].out, choices[c2].in);
        double& slot = dp[(mask | bit) * C + c2];
        if (v < slot) slot = v, parent[(mask | bit) * C + c2] = static_cast<std::uint32_t>(c);
      }
    }
  double best = inf;
  std::size_t best_c = 0;
  for (std::size_t c = 0; c < C; ++c) {
    const double v = dp[full * C + c] + (ends.end_free ? 0.0 : dist(choices[c].out, ends.end));
    if (v < best) best = v, best_c = c;
  }
  std::vector<std::uint32_t> sequence;
  for (std::size_t mask = full, c = best_c; c != kNone;) {
    sequence.push_back(static_cast<std::uint32_t>(c));
    const std::uint32_t pc = parent[mask * C + c];
    mask &= ~(std::size_t{1} << choices[c].stroke);
    c = pc == kNone ? kNone : pc;
  }
  std::reverse(sequence.begin(), sequence.end());
  std::vector<GridStroke> out;
  out.reserve(n);
  for (std::uint32_t c : sequence) {
    const Choice& ch = choices[c];
    GridStroke s = std::move(strokes[ch.stroke]);
    if (s.closed)
      rotate_closed(s, ch.entry);
    else if (ch.entry)
      std::reverse(s.vertices.begin(), s.vertices.end());
    out.push_back(std::move(s));
  }
  strokes = std::move(out);
  return true;
}

}  // namespace hlr::plan
