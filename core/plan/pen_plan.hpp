// Pen planning: turns the pieces of one page into strokes in plotting order (DESIGN.md "Pen planning").
//
// Pieces are snapped to the device grid, duplicates and overlapping collinear pieces merged, each
// connected component drawn with the fewest strokes (Euler trails: max(1, odd/2)), and the strokes
// ordered and oriented to cut pen-up travel. Pieces of different pens (or layers) are never joined;
// pens are drawn one after another in increasing pen number, visible layer before hidden within a pen.
#pragma once

#include <cstddef>
#include <vector>

#include "core/geometry/vector.hpp"
#include "core/plan/plot_stroke.hpp"

namespace hlr {

// A straight piece in page millimetres (top-left origin, y down).
struct PlotPiece {
  Point2 a, b;
  int pen = 1;
  StrokeLayer layer = StrokeLayer::Visible;
  int level = 0;  // hidden pieces drawn by occlusion level: 1, 2, …; else 0 (PlotStroke::level)
};

enum class PenOrder {
  None,       // file order: pieces as given, a piece starting where the previous ended continues its stroke
  Greedy,     // Euler strokes, then nearest-endpoint ordering with reversal
  Optimized,  // Euler strokes with matched odd vertices, drawn circuit by circuit, then 2-opt / Or-opt
              // within the work cap (PlanOptions::effort); never more pen-up travel than Greedy on drawings
              // of up to kGreedyCheckEdges graph edges (both are built, the better kept); beyond that size
              // the greedy plan costs as much as the rest of planning and loses clearly (0.45–0.7× its pen-up
              // on every bench/ scene), so it is not built
};

// Optimized builds the greedy plan for comparison only up to this many drawing-graph edges (all groups).
inline constexpr std::size_t kGreedyCheckEdges = 1024;

// The plotter's speeds, for the time estimate (defaults: a 7475A-class pen plotter).
struct PlotterSpeeds {
  double pen_down_mm_per_s = 380;
  double pen_up_mm_per_s = 380;
  double lift_s = 0.1;  // one pen-up plus pen-down
};

// The improvement work per stroke by default, and the most --plan-effort takes.
inline constexpr std::size_t kDefaultPlanEffort = 500;
inline constexpr std::size_t kMaxPlanEffort = 100000;

struct PlanOptions {
  PenOrder order = PenOrder::Optimized;
  double grid_mm = 0.025;  // endpoints snap to multiples of this (the device's plotter unit)
  Point2 home{0, 0};       // the pen starts here and returns here (page mm)
  // Optimized: the improvement passes' work per stroke (candidate moves evaluated plus tour positions
  // rewritten; core/plan/stroke_order.hpp). Counted in work, never in time, so that the plan depends only
  // on the pieces and the options; 0 keeps the circuit order.
  std::size_t effort = kDefaultPlanEffort;
  PlotterSpeeds speeds;
  // A piece is split at (joined to) every vertex exactly on it between its end points, and at every loose
  // end (a vertex where a single piece ends) within this many grid units of it: T-junctions that snapping
  // moved off the line they meet (by up to √2 units). 0 joins only vertices exactly on the snapped piece.
  // See core/plan/pen_graph.hpp.
  double merge_tolerance_grid = 1.5;
  // With 2 or more: the drawing graph's splitting and the matching's neighbour search run in parts as
  // tasks of the caller's arena, and (Optimized) the greedy plan it is compared with (see
  // kGreedyCheckEdges) is built beside the optimized one. The result is the same for any value.
  int threads = 1;
};

struct PlanStats {
  std::size_t pieces = 0;         // pieces given
  std::size_t merged_pieces = 0;  // edges of the drawing graph after snapping and merging
  double pen_down_mm = 0;
  double pen_up_mm = 0;       // home → first stroke, between strokes, last stroke → home
  double pen_up_mean_mm = 0;  // over the pen-up moves (strokes + 1 of them; 0 when there is no stroke)
  double pen_up_median_mm = 0;
  std::size_t lifts = 0;             // strokes drawn
  std::size_t lift_lower_bound = 0;  // sum over components of max(1, odd/2), per pen and layer
  double plot_seconds = 0;           // pen_down/v_down + pen_up/v_up + lifts·lift_s
  double planning_ms = 0;
  std::size_t dropped_pieces = 0;  // zero length on the grid, not finite, or beyond ±2^29 grid units
  std::size_t components = 0;      // of the drawing graphs, summed over pens and layers
  std::size_t odd_vertices = 0;
  std::size_t improvement_moves = 0;  // Optimized: improving 2-opt / Or-opt / re-entry moves applied
  bool kept_greedy = false;           // Optimized: the greedy plan was built, was shorter and was kept
  bool effort_exhausted = false;      // Optimized: the work cap (PlanOptions::effort) stopped the improvement
  // Hidden strokes cut into pen-down dashes for a plotter (core/plan/hidden_dashes.hpp): the dashes drawn,
  // each a lift of its own, counted in `lifts` (lift_lower_bound stays the undashed drawing's).
  std::size_t hidden_dashes = 0;
};

struct PenPlan {
  std::vector<PlotStroke> strokes;  // in plotting order
  PlanStats stats;
};

// Throws std::invalid_argument when options.grid_mm is not finite and positive. Pieces that are not finite,
// lie beyond ±2^29 grid units, or snap to a point are dropped (stats.dropped_pieces). Strokes' points are
// grid points (multiples of grid_mm). None keeps the snapped pieces in file order within each pen and
// layer, joining a piece to the previous one when it starts where that one ended. Greedy and Optimized
// draw every edge of the merged drawing graph exactly once, with lifts == lift_lower_bound, dropping a
// stroke's middle point only where the two grid segments meeting there are exactly collinear.
// Optimized pairs the odd vertices of each pen and layer by a minimum-weight matching (exact up to 16 of
// them; greedy plus exchanges beyond), follows the augmented Euler circuits so that the pen-up moves are
// the matched pairs, links the circuits nearest first, and improves the order with 2-opt and Or-opt;
// groups of up to 10 strokes are ordered exactly instead. Its work is capped in proportion to the stroke
// count (PlanOptions::effort), never by the clock: the plan is the same on an idle and a loaded machine.
PenPlan plan_pen_strokes(const std::vector<PlotPiece>& pieces, const PlanOptions& options = {});

// Sets the figures of what `strokes` draw: lifts, pen_down_mm, the pen-up moves from options.home through
// the strokes and back (pen_up_mm, mean, median) and plot_seconds from options.speeds.
void fill_travel_stats(const std::vector<PlotStroke>& strokes, const PlanOptions& options, PlanStats& stats);

}  // namespace hlr
