#include "core/plan/pen_plan.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "core/parallel.hpp"
#include "core/plan/euler_strokes.hpp"
#include "core/plan/odd_matching.hpp"
#include "core/plan/pen_graph.hpp"
#include "core/plan/stroke_order.hpp"

namespace hlr {
namespace {

using plan::GridSegment;
using plan::GridStroke;
using plan::PenGraph;
using plan::Pt;
using plan::TourEnds;
using Clock = std::chrono::steady_clock;

struct Group {
  int pen;
  StrokeLayer layer;
  int level;
  std::vector<GridSegment> segments;  // snapped, non-degenerate, in file order
  PenGraph graph;
};

// Snaps one coordinate; false when it is not finite or beyond the grid range.
bool snap(double mm, double grid, std::int64_t& out) {
  const double g = mm / grid;
  if (!std::isfinite(g) || std::fabs(g) > static_cast<double>(plan::kMaxGridCoordinate)) return false;
  out = std::llround(g);
  return true;
}

// The pieces snapped and sorted into groups by (pen, layer, level): Visible (0) before Hidden (1) before
// Hatch (2), hidden levels ascending; each group's segments in piece order. Parts of the pieces are snapped
// side by side, each into runs of its own, and the runs joined group by group in part order: the
// 10⁶-triangle torus's 377 000 pieces took 13 ms on one core.
std::vector<Group> snap_groups(const std::vector<PlotPiece>& pieces, double grid, unsigned threads,
                               std::size_t& dropped) {
  using Key = std::tuple<int, int, int>;
  struct Run {
    Key key;
    std::vector<GridSegment> segments;
  };
  struct Part {
    std::vector<Run> runs;  // consecutive pieces mostly share their group: a run per change of group
    std::size_t dropped = 0;
  };
  constexpr std::size_t kPartPieces = 16384;
  std::vector<Part> parts((pieces.size() + kPartPieces - 1) / kPartPieces);
  parallel_chunks(parts.size(), threads_for(pieces.size(), 2 * kPartPieces, threads), [&](std::size_t k) {
    Part part;  // filled here, stored once: the parts lie side by side
    const std::size_t end = std::min(pieces.size(), (k + 1) * kPartPieces);
    for (std::size_t i = k * kPartPieces; i < end; ++i) {
      const PlotPiece& p = pieces[i];
      GridSegment s;
      if (!snap(p.a.x, grid, s.a.x) || !snap(p.a.y, grid, s.a.y) || !snap(p.b.x, grid, s.b.x) ||
          !snap(p.b.y, grid, s.b.y) || s.a == s.b) {
        ++part.dropped;
        continue;
      }
      const Key key{p.pen, static_cast<int>(p.layer), p.level};
      if (part.runs.empty() || part.runs.back().key != key) part.runs.push_back({key, {}});
      part.runs.back().segments.push_back(s);
    }
    parts[k] = std::move(part);
  });
  // Each group's size, then, in the same map, its place among the groups in key order.
  std::map<Key, std::size_t> place;
  for (const Part& part : parts) {
    dropped += part.dropped;
    for (const Run& run : part.runs) place[run.key] += run.segments.size();
  }
  std::vector<Group> groups;
  groups.reserve(place.size());
  for (auto& [key, size_then_place] : place) {
    groups.push_back(
        Group{std::get<0>(key), static_cast<StrokeLayer>(std::get<1>(key)), std::get<2>(key), {}, {}});
    groups.back().segments.reserve(size_then_place);
    size_then_place = groups.size() - 1;
  }
  for (Part& part : parts)
    for (Run& run : part.runs) {
      std::vector<GridSegment>& to = groups[place.at(run.key)].segments;
      to.insert(to.end(), run.segments.begin(), run.segments.end());
      std::vector<GridSegment>().swap(run.segments);
    }
  return groups;
}

// A planned group: strokes as graph vertex lists.
struct GroupStrokes {
  std::vector<GridStroke> strokes;
};

struct Sequence {
  std::vector<GroupStrokes> groups;
  double travel = 0;  // grid units
  std::size_t moves = 0;
  bool capped = false;
};

// `neighbours`: the matching's neighbour lists over g.odd, as long as improve_order() will read them when
// every stroke is open (odd / 2 strokes), so that it need not search again.
std::size_t shared_list_length(const PenGraph& g) {
  return std::max(plan::kMatchingNeighbours, plan::improve_list_length(g.odd.size() / 2));
}
std::vector<plan::VertexPair> matched_pairing(const PenGraph& g, std::vector<std::uint32_t>& neighbours,
                                              unsigned threads) {
  std::vector<Pt> points;
  points.reserve(g.odd.size());
  for (std::uint32_t v : g.odd)
    points.push_back({static_cast<double>(g.vertices[v].x), static_cast<double>(g.vertices[v].y)});
  std::vector<plan::VertexPair> pairs;
  for (const auto& [i, j] : plan::min_weight_matching(points, &neighbours, shared_list_length(g), threads))
    pairs.emplace_back(g.odd[i], g.odd[j]);
  return pairs;
}

// `effort` (Optimized): the improvement passes' work per stroke of each group. `threads` as for
// parallel_chunks (the same sequence for any value).
Sequence plan_sequence(const std::vector<Group>& groups, Pt home, bool optimize, std::size_t effort,
                       unsigned threads) {
  Sequence out;
  Pt here = home;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    const PenGraph& g = groups[gi].graph;
    const TourEnds ends{here, home, gi + 1 < groups.size()};
    GroupStrokes gs;
    std::vector<std::uint32_t> neighbours;
    gs.strokes = plan::euler_strokes(
        g, optimize ? matched_pairing(g, neighbours, threads) : plan::sequential_pairing(g));
    if (!optimize) {
      plan::order_greedy(gs.strokes, g.vertices, ends);
    } else if (plan::order_exact(gs.strokes, g.vertices, ends)) {
      // Small enough for the exact order: try the sequential pairing's strokes too, keep the shorter.
      std::vector<GridStroke> other = plan::euler_strokes(g, plan::sequential_pairing(g));
      if (plan::order_exact(other, g.vertices, ends) &&
          plan::tour_travel(other, g.vertices, ends) < plan::tour_travel(gs.strokes, g.vertices, ends))
        gs.strokes = std::move(other);
    } else {
      plan::order_circuits(gs.strokes, g.vertices, ends);
      const plan::SharedNeighbours shared{&g.odd, &neighbours, shared_list_length(g)};
      const plan::ImproveResult r = plan::improve_order(gs.strokes, g.vertices, ends, effort, &shared);
      out.moves += r.moves;
      out.capped = out.capped || r.capped;
    }
    out.travel += plan::tour_travel(gs.strokes, g.vertices, ends);
    if (!gs.strokes.empty()) {
      const GridPoint last = g.vertices[gs.strokes.back().vertices.back()];
      here = {static_cast<double>(last.x), static_cast<double>(last.y)};
    }
    out.groups.push_back(std::move(gs));
  }
  return out;
}

Point2 to_mm(GridPoint p, double grid) {
  return {static_cast<double>(p.x) * grid, static_cast<double>(p.y) * grid};
}

// Graph strokes → page strokes, dropping middle points where the path goes straight on exactly.
void emit_strokes(const std::vector<Group>& groups, const Sequence& seq, double grid,
                  std::vector<PlotStroke>& out) {
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    const std::vector<GridPoint>& v = groups[gi].graph.vertices;
    for (const GridStroke& s : seq.groups[gi].strokes) {
      PlotStroke ps;
      ps.pen = groups[gi].pen;
      ps.layer = groups[gi].layer;
      ps.level = groups[gi].level;
      ps.points.reserve(s.vertices.size());
      GridPoint kept = v[s.vertices.front()];
      ps.points.push_back(to_mm(kept, grid));
      for (std::size_t k = 1; k + 1 < s.vertices.size(); ++k) {
        const GridPoint b = v[s.vertices[k]], c = v[s.vertices[k + 1]];
        const std::int64_t ux = b.x - kept.x, uy = b.y - kept.y, wx = c.x - b.x, wy = c.y - b.y;
        if (ux * wy - uy * wx == 0 && ux * wx + uy * wy > 0) continue;  // straight on
        kept = b;
        ps.points.push_back(to_mm(b, grid));
      }
      ps.points.push_back(to_mm(v[s.vertices.back()], grid));
      out.push_back(std::move(ps));
    }
  }
}

void file_order_strokes(const std::vector<Group>& groups, double grid, std::vector<PlotStroke>& out) {
  for (const Group& g : groups) {
    GridPoint end{};
    bool open = false;
    for (const GridSegment& s : g.segments) {
      if (!open || !(s.a == end)) {
        PlotStroke ps;
        ps.pen = g.pen;
        ps.layer = g.layer;
        ps.level = g.level;
        ps.points.push_back(to_mm(s.a, grid));
        out.push_back(std::move(ps));
        open = true;
      }
      out.back().points.push_back(to_mm(s.b, grid));
      end = s.b;
    }
  }
}

}  // namespace

void fill_travel_stats(const std::vector<PlotStroke>& strokes, const PlanOptions& o, PlanStats& st) {
  st.lifts = strokes.size();
  st.pen_down_mm = 0;
  for (const PlotStroke& s : strokes)
    for (std::size_t k = 1; k < s.points.size(); ++k)
      st.pen_down_mm += distance(s.points[k - 1], s.points[k]);
  st.pen_up_mm = st.pen_up_mean_mm = st.pen_up_median_mm = 0;
  if (!strokes.empty()) {
    std::vector<double> moves;
    moves.reserve(strokes.size() + 1);
    Point2 here = o.home;
    for (const PlotStroke& s : strokes) {
      moves.push_back(distance(here, s.points.front()));
      here = s.points.back();
    }
    moves.push_back(distance(here, o.home));
    for (double m : moves) st.pen_up_mm += m;
    st.pen_up_mean_mm = st.pen_up_mm / static_cast<double>(moves.size());
    const std::size_t h = moves.size() / 2;  // the median by selection: moves[h] and the largest below it
    std::nth_element(moves.begin(), moves.begin() + static_cast<std::ptrdiff_t>(h), moves.end());
    st.pen_up_median_mm =
        moves.size() % 2
            ? moves[h]
            : 0.5 * (*std::max_element(moves.begin(), moves.begin() + static_cast<std::ptrdiff_t>(h)) +
                     moves[h]);
  }
  st.plot_seconds = st.pen_down_mm / o.speeds.pen_down_mm_per_s + st.pen_up_mm / o.speeds.pen_up_mm_per_s +
                    static_cast<double>(st.lifts) * o.speeds.lift_s;
}

PenPlan plan_pen_strokes(const std::vector<PlotPiece>& pieces, const PlanOptions& options) {
  const Clock::time_point t0 = Clock::now();
  const double grid = options.grid_mm;
  if (!std::isfinite(grid) || !(grid > 0))
    throw std::invalid_argument("plan_pen_strokes: grid_mm must be positive");
  PenPlan plan;
  PlanStats& st = plan.stats;
  st.pieces = pieces.size();
  const unsigned threads = options.threads >= 2 ? 0 : 1;  // 0: parts as tasks of the caller's arena
  std::vector<Group> groups = snap_groups(pieces, grid, threads, st.dropped_pieces);
  for (Group& g : groups) {
    g.graph = plan::build_pen_graph(g.segments, options.merge_tolerance_grid, threads);
    st.merged_pieces += g.graph.edges.size();
    st.lift_lower_bound += g.graph.lift_lower_bound;
    st.components += g.graph.components;
    st.odd_vertices += g.graph.odd.size();
  }
  const Pt home{options.home.x / grid, options.home.y / grid};
  if (options.order == PenOrder::None) {
    file_order_strokes(groups, grid, plan.strokes);
  } else {
    const std::size_t effort = std::min(options.effort, kMaxPlanEffort);
    Sequence chosen;
    if (options.order == PenOrder::Optimized) {
      // The greedy plan, for the never-worse-than-Greedy guarantee on small drawings (where the matching
      // and the local search have least to work with): built beside the optimized one when allowed (as a
      // task of the caller's arena).
      Sequence optimized;
      auto best = [&] { optimized = plan_sequence(groups, home, true, effort, threads); };
      if (st.merged_pieces <= kGreedyCheckEdges) {
        auto greedy = [&] { chosen = plan_sequence(groups, home, false, effort, 1); };
        if (options.threads >= 2) {
          tbb::parallel_invoke(greedy, best);
        } else {
          greedy();
          best();
        }
      } else {
        best();
      }
      st.improvement_moves = optimized.moves;
      st.effort_exhausted = optimized.capped;
      if (st.merged_pieces > kGreedyCheckEdges || optimized.travel <= chosen.travel)
        chosen = std::move(optimized);
      else
        st.kept_greedy = true;
    } else {
      chosen = plan_sequence(groups, home, false, effort, threads);
    }
    emit_strokes(groups, chosen, grid, plan.strokes);
  }
  fill_travel_stats(plan.strokes, options, st);
  st.planning_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return plan;
}

}  // namespace hlr
