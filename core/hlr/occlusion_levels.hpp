// Occlusion levels: how many surfaces lie in front of each hidden part of an edge.
//
// Every face in front of a point hides it over one interval of the edge's parameter (occlusion.hpp adds one
// or more per face, disjoint for one face). Counting how many of those intervals cover a point gives the
// number of surfaces between it and the eye. Faces that meet along a shared edge give intervals that meet
// only up to rounding, so the count steps by one for a sliver as long as that rounding; such negligible
// pieces join their neighbour, exactly as the hidden runs themselves are closed and cleaned
// (render_frame.cpp), so the levels split each hidden run and never move its ends.
//
// Where back faces are culled (frame_setup.hpp, BackFaces::CountLevels) a front face's cover stands for
// two surfaces, and an edge on the solid's back lies on one of the surfaces so counted: its `surplus`.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/hlr/interval_set.hpp"

namespace hlr {

// The parameter interval over which one face hides an edge, and how many surfaces it stands for.
struct LevelCover {
  double lo = 0, hi = 0;
  int surfaces = 1;
};

struct LevelPiece {
  double lo = 0, hi = 0;
  std::uint16_t level = 0;
};

struct LevelScratch {
  std::vector<std::pair<double, int>> events;  // (parameter, + surfaces entering a cover, − leaving it)
  std::vector<LevelPiece> steps;               // the count over [0, 1], piece by piece
  std::vector<LevelPiece> run;                 // one hidden run's pieces while they are cleaned
};

// Splits each of `hidden_runs` (sorted, disjoint) into pieces of one level: the surfaces of the `covers`
// over it (overlaps kept), less `surplus`. A piece for which is_negligible(lo, hi) holds joins the
// piece before it (the one after, at a run's start); neighbours of one level become one piece. Every piece
// of a hidden run has a level of at least 1. Appends to `out`.
template <typename IsNegligible>
void split_by_level(const std::vector<LevelCover>& covers, int surplus,
                    const std::vector<Interval>& hidden_runs, IsNegligible&& is_negligible,
                    LevelScratch& scratch, std::vector<LevelPiece>& out) {
  auto& events = scratch.events;
  events.clear();
  for (const LevelCover& c : covers) {
    if (c.hi <= c.lo) continue;
    events.emplace_back(c.lo, c.surfaces);
    events.emplace_back(c.hi, -c.surfaces);
  }
  std::sort(events.begin(), events.end());
  auto& steps = scratch.steps;
  steps.clear();
  int count = -surplus;
  double from = 0;
  for (std::size_t i = 0; i < events.size();) {
    const double t = events[i].first;
    if (t > from) steps.push_back({from, t, static_cast<std::uint16_t>(std::max(count, 0))});
    for (; i < events.size() && events[i].first == t; ++i) count += events[i].second;
    from = std::max(from, t);
  }
  if (from < 1) steps.push_back({from, 1, static_cast<std::uint16_t>(std::max(count, 0))});

  auto& run = scratch.run;
  std::size_t k = 0;  // the first step that may overlap the current run
  for (const Interval& h : hidden_runs) {
    while (k < steps.size() && steps[k].hi <= h.lo) ++k;
    run.clear();
    for (std::size_t j = k; j < steps.size() && steps[j].lo < h.hi; ++j) {
      const LevelPiece p{std::max(steps[j].lo, h.lo), std::min(steps[j].hi, h.hi), steps[j].level};
      if (p.hi > p.lo) run.push_back(p);
    }
    if (run.empty()) {  // a run no cover reaches: cannot happen for runs made of the covers; keep it whole
      out.push_back({h.lo, h.hi, 1});
      continue;
    }
    run.front().lo = h.lo;
    run.back().hi = h.hi;
    const std::size_t first = out.size();
    double pending_lo = -1;  // a negligible start waiting for the piece after it
    for (const LevelPiece& p : run) {
      const bool has_previous = out.size() > first;
      if (is_negligible(p.lo, p.hi) && (has_previous || &p != &run.back())) {
        if (has_previous) {
          out.back().hi = p.hi;
        } else if (pending_lo < 0) {
          pending_lo = p.lo;
        }
        continue;
      }
      LevelPiece q = p;
      if (pending_lo >= 0) {
        q.lo = pending_lo;
        pending_lo = -1;
      }
      q.level = std::max<std::uint16_t>(q.level, 1);
      if (has_previous && out.back().level == q.level) {
        out.back().hi = q.hi;
      } else {
        out.push_back(q);
      }
    }
  }
}

}  // namespace hlr
