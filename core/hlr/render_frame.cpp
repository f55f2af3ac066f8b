#include "core/hlr/render_frame.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "core/first_touch.hpp"
#include "core/geometry/clip2d.hpp"
#include "core/hlr/coincident_pieces.hpp"
#include "core/hlr/face_grid.hpp"
#include "core/hlr/frame_setup.hpp"
#include "core/hlr/occlusion.hpp"
#include "core/hlr/occlusion_levels.hpp"
#include "core/hlr/smooth_contours.hpp"
#include "core/parallel.hpp"

namespace hlr {
namespace {

// Restricts a candidate to the part inside the picture frame (Desens' WINDOW); false if none is.
bool clip_to_frame(Candidate& c, const Camera& camera) {
  if (!camera.frame) return true;
  const auto range = clip_segment_to_rect(c.pic0, c.pic1, *camera.frame);
  if (!range) return false;
  const auto [s0, s1] = *range;
  if (s0 <= 0 && s1 >= 1) return true;
  const double t0 = view_param(c, camera, s0), t1 = view_param(c, camera, s1);
  const Point3 v0 = lerp(c.view0, c.view1, t0), v1 = lerp(c.view0, c.view1, t1);
  const Point2 p0 = lerp(c.pic0, c.pic1, s0), p1 = lerp(c.pic0, c.pic1, s1);
  c.view0 = v0;
  c.view1 = v1;
  c.pic0 = p0;
  c.pic1 = p1;
  return true;
}

bool is_own_face(const FrameSetup& setup, const Candidate& c, const Occluder& o) {
  if (c.source == SegmentSource::Contour)  // its own face and those near it (smooth_contours.hpp)
    return o.object == c.object &&
           near_contour_face(*setup.scene->objects[c.object].solid, c.own_face0, o.face);
  return (o.object == c.own_object0() && o.face == c.own_face0) ||
         (o.object == c.own_object1() && o.face == c.own_face1);
}

struct Worker {
  const FrameSetup& setup;
  const Camera& camera;
  const FaceGrid* grid;
  const HlrOptions& options;
  Affine3 world_from_view;
  std::vector<std::uint32_t> stamp;
  std::vector<std::uint32_t> near;  // the occluders met near the current edge
  OcclusionScratch scratch;
  IntervalSet hidden;
  std::vector<Interval> visible;  // the complement of `hidden`, room reused
  std::size_t face_tests = 0;
  std::vector<VisibleSegment> buffer;  // the current chunk's pieces
  std::vector<LevelCover> covers;      // occlusion levels: the hidden intervals, one or more a face
  LevelScratch level_scratch;
  std::vector<LevelPiece> levels;

  Point2 picture_point(const Candidate& c, double t) const {
    return lerp(c.pic0, c.pic1, picture_param(c, camera, t));
  }

  void emit(const Candidate& c, double t0, double t1, std::uint16_t level, std::vector<VisibleSegment>& out) {
    const double s0 = picture_param(c, camera, t0), s1 = picture_param(c, camera, t1);
    VisibleSegment seg;
    seg.p0 = world_from_view.apply(lerp(c.view0, c.view1, t0));
    seg.p1 = world_from_view.apply(lerp(c.view0, c.view1, t1));
    seg.s0 = lerp(c.pic0, c.pic1, s0);
    seg.s1 = lerp(c.pic0, c.pic1, s1);
    if (distance(seg.s0, seg.s1) <= c.picture_tolerance || (level > 0 && c.hatch)) return;
    seg.object = c.object;
    seg.edge = c.edge;
    seg.other = c.other;
    seg.source = c.source;
    seg.hatch = c.hatch;
    seg.hidden = level > 0;
    seg.level = level;
    out.push_back(seg);
  }

  void process(std::uint32_t index, std::vector<VisibleSegment>& out) {
    const Candidate& c = setup.candidates[index];
    const bool count_levels = options.max_level > 0;
    if (c.culled && !count_levels) {
      if (options.include_hidden) emit(c, 0, 1, 1, out);
      return;
    }
    hidden.clear();
    const double max_depth = std::max(c.view0.z, c.view1.z);
    Rect2 box = Rect2::none();
    box.include(c.pic0);
    box.include(c.pic1);
    // In three passes, each fetching ahead what the next reads — the occluders near the edge, then the
    // outlines of those that may hide it — so that their loads overlap: occluders come from all over
    // memory (a scan's faces are in no order), and one at a time each test waited on two of them.
    near.clear();
    grid->for_each_near(c.pic0, c.pic1, max_depth, stamp, index + 1, [&](std::uint32_t id) {
      __builtin_prefetch(&setup.occluders[id]);
      near.push_back(id);
    });
    std::size_t kept = 0;
    for (const std::uint32_t id : near) {
      const Occluder& o = setup.occluders[id];
      if (o.min_depth >= max_depth || !o.bounds.overlaps(box) || is_own_face(setup, c, o)) continue;
      __builtin_prefetch(&setup.polygon_points[o.first_point]);
      __builtin_prefetch(&setup.ring_ends[o.first_ring]);
      near[kept++] = id;
    }
    covers.clear();
    double added = 0;  // the lengths of the hidden intervals added, overlaps counted twice
    for (std::size_t k = 0; k < kept; ++k) {
      const Occluder& o = setup.occluders[near[k]];
      const std::size_t before = hidden.items().size();
      add_hidden_intervals(setup, camera, c, o, scratch, hidden);
      ++face_tests;
      if (!count_levels) {
        // Hidden whole, the edge stays hidden whole: the faces left cannot change what is drawn (only
        // level counts need every cover). They can cover [0, 1] only once their lengths add up to it.
        for (std::size_t i = before; i < hidden.items().size(); ++i)
          added += hidden.items()[i].hi - hidden.items()[i].lo;
        if (added >= 1 && hidden.covers_all()) break;
        continue;
      }
      const int surfaces =
          setup.cull[o.object] ? 2 : 1;  // a culled solid's front face and the back behind it
      for (std::size_t i = before; i < hidden.items().size(); ++i)
        covers.push_back({hidden.items()[i].lo, hidden.items()[i].hi, surfaces});
    }
    // Hidden runs that meet up to rounding (across a shared face edge) are one run: the sliver between
    // them is not a visible piece.
    // A hidden run of negligible length (an edge grazing a face's outline) does not split what is seen.
    auto negligible = [&](double t0, double t1) {
      return distance(picture_point(c, t0), picture_point(c, t1)) <= c.picture_tolerance;
    };
    hidden.close_gaps(negligible);
    hidden.drop(negligible);
    if (c.culled) {  // on its solid's back (counting levels): hidden whole, whatever rounding left between
                     // covers
      hidden.clear();
      hidden.add(0, 1);
    }
    hidden.complement_into(visible);
    for (const Interval& v : visible) emit(c, v.lo, v.hi, 0, out);
    if (count_levels) {
      levels.clear();
      split_by_level(covers, c.culled ? 1 : 0, hidden.normalize(), negligible, level_scratch, levels);
      for (const LevelPiece& p : levels)
        if (p.level <= options.max_level) emit(c, p.lo, p.hi, p.level, out);
    } else if (options.include_hidden) {
      for (const Interval& h : hidden.normalize()) emit(c, h.lo, h.hi, 1, out);
    }
  }
};

// A run of candidates examined: the order they were taken in, and per chunk of that order the pieces and
// how many each candidate gave.
struct Examined {
  struct Chunk {
    std::vector<VisibleSegment> pieces;
    std::vector<std::uint32_t> counts;  // per candidate of the chunk, in the order examined
  };
  static constexpr std::uint32_t kChunk = 256;
  std::vector<std::uint32_t> order;
  std::vector<Chunk> chunks;
};

// The pieces of the runs, which examined candidates 0 … n − 1 between them, in candidate order; each
// chunk is released once copied. The chunks are copied side by side (`threads` as for parallel_chunks):
// each fills its own candidates' places.
std::vector<VisibleSegment> in_candidate_order(std::vector<Examined>& runs, std::uint32_t n,
                                               unsigned threads) {
  std::vector<std::uint32_t> offset(n + 1, 0);  // of each candidate's pieces
  std::vector<std::pair<Examined*, std::size_t>> chunks;
  for (Examined& run : runs)
    for (std::size_t k = 0; k < run.chunks.size(); ++k) {
      chunks.emplace_back(&run, k);
      for (std::size_t j = 0; j < run.chunks[k].counts.size(); ++j)
        offset[run.order[k * Examined::kChunk + j] + 1] = run.chunks[k].counts[j];
    }
  for (std::uint32_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
  std::vector<VisibleSegment> segments;
  resize_touched(segments, offset[n], threads);
  constexpr std::size_t kMinPieces = 16384;  // fewer are copied sooner than shared out
  parallel_chunks(chunks.size(), threads_for(offset[n], kMinPieces, threads), [&](std::size_t c) {
    const auto [run, k] = chunks[c];
    Examined::Chunk& chunk = run->chunks[k];
    const VisibleSegment* from = chunk.pieces.data();
    for (std::size_t j = 0; j < chunk.counts.size(); ++j) {
      std::copy(from, from + chunk.counts[j],
                segments.begin() + offset[run->order[k * Examined::kChunk + j]]);
      from += chunk.counts[j];
    }
    chunk = Examined::Chunk{};
  });
  return segments;
}

// Restricts candidates [from, end) to the picture frame, sets their tolerances and widens `domain` to
// them; drops what lies outside the frame. Returns the new end.
std::size_t clip_candidates(FrameSetup& setup, std::size_t from, const Camera& camera, Rect2& domain,
                            unsigned threads) {
  if (!camera.frame) {  // none dropped: by parts side by side (`threads` as for parallel_chunks)
    const std::size_t n = setup.candidates.size() - from;
    constexpr std::size_t kPart = 16384;
    std::vector<Rect2> part_domain((n + kPart - 1) / kPart, Rect2::none());
    parallel_chunks(part_domain.size(), threads_for(n, 2 * kPart, threads), [&](std::size_t k) {
      Rect2 part = Rect2::none();  // stored once: the parts' rectangles share cache lines
      for (std::size_t i = from + k * kPart; i < from + std::min(n, (k + 1) * kPart); ++i) {
        Candidate& c = setup.candidates[i];
        set_picture_tolerance(c, camera, setup.length_tolerance);
        part.include(c.pic0);
        part.include(c.pic1);
      }
      part_domain[k] = part;
    });
    for (const Rect2& part : part_domain)
      domain.include({part.xmin, part.ymin}), domain.include({part.xmax, part.ymax});
    return setup.candidates.size();
  }
  std::size_t kept = from;
  for (std::size_t i = from; i < setup.candidates.size(); ++i) {
    Candidate c = setup.candidates[i];
    if (!clip_to_frame(c, camera)) continue;
    set_picture_tolerance(c, camera, setup.length_tolerance);
    domain.include(c.pic0);
    domain.include(c.pic1);
    setup.candidates[kept++] = c;
  }
  setup.candidates.resize(kept);
  return kept;
}

}  // namespace

FrameResult render_frame(const Scene& scene, const Camera& camera, const HlrOptions& options) {
  const auto check_cancel = [&] {
    if (options.cancel && options.cancel->load(std::memory_order_relaxed)) throw RenderCancelled();
    if (options.deadline != std::chrono::steady_clock::time_point::max() &&
        std::chrono::steady_clock::now() > options.deadline)
      throw FrameTimedOut();
  };
  check_cancel();
  FrameStats::Stages ms;
  auto last = std::chrono::steady_clock::now();
  auto lap = [&last] {  // ms since the last lap
    const auto now = std::chrono::steady_clock::now();
    const double d = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
    return d;
  };
  // Where a solid passes through itself is searched for once per solid (and kept with it). An open
  // solid's edges do not need it, so the search runs beside their preparation and examination and takes
  // up what of that work runs on one core; the lines it finds are examined last. Only in the caller's
  // arena (threads 0): one thread means this thread only.
  tbb::task_group crossing_search;
  struct WaitOnExit {
    tbb::task_group& group;
    bool armed;
    void wait() {  // rethrows what the search threw (out of memory)
      if (!armed) return;
      armed = false;
      group.wait();
    }
    ~WaitOnExit() {  // the frame is failing already: what the search threw too is not news
      if (!armed) return;
      try {
        group.wait();
      } catch (...) {
      }
    }
  } search{crossing_search, options.intersection_lines && options.threads == 0};
  const BackFaces back_faces = options.max_level > 0 ? BackFaces::CountLevels : BackFaces::Cull;
  // A closed solid's back faces may be culled only when it does not pass through itself (frame_setup.cpp).
  // Its search too runs beside the edges' preparation and examination, which take the answer to be "it
  // does not" (scenes and scans almost never do); once it is done the guess is checked, and where it was
  // wrong the edges are prepared and examined again without culling. What of either runs on one core is
  // then taken up by the other (fandisk's frame 14 ms sooner). With one thread, or past a quarter of a
  // million faces, the search comes first: a 10⁶-triangle torus gained nothing from the overlap but held
  // the search's 220 MB beside the frame's (0.68 → 0.9 KiB a face).
  constexpr std::size_t kOverlapFaces = 250'000;
  std::size_t faces = 0;
  for (const SceneObject& o : scene.objects) faces += o.solid->faces.size();
  const bool guess = search.armed && faces <= kOverlapFaces;
  if (guess) {
    crossing_search.run([&scene] {
      for (const SceneObject& o : scene.objects) o.solid->self_crossings();
    });
  } else {
    for (const SceneObject& o : scene.objects)
      if (o.solid->closed) o.solid->self_crossings();
  }
  ms.self_crossings = lap();

  FrameSetup setup;
  Rect2 domain = Rect2::none();
  std::size_t edges = 0;
  std::unique_ptr<const FaceGrid> grid;
  auto prepare = [&](bool assume_uncrossed) {
    setup =
        prepare_frame(scene, camera, options.include_hidden, options.threads, assume_uncrossed, back_faces);
    check_cancel();
    ms.setup += lap();
    // Only what lies inside the picture frame is examined.
    domain = Rect2::none();
    edges = clip_candidates(setup, 0, camera, domain, options.threads);
    grid = std::make_unique<const FaceGrid>(setup, domain, options.threads);
    ms.grid += lap();
  };
  prepare(guess);

  const Affine3 world_from_view = camera.viewFromWorld.inverse();
  // One worker (scratch buffers, stamps) per thread that takes part; chunks go to whichever is free.
  tbb::enumerable_thread_specific<Worker> workers([&] {
    return Worker{setup,
                  camera,
                  grid.get(),
                  options,
                  world_from_view,
                  std::vector<std::uint32_t>(setup.occluders.size(), 0),
                  {},
                  {},
                  {},
                  {},
                  0,
                  {},
                  {},
                  {},
                  {}};
  });
  // Candidates [begin, end) are examined in the order of the grid cell their midpoint lies in (a counting
  // sort): one after another they then meet the same occluders while those are still in cache, where a
  // scan's edges come in no spatial order and each test waited on memory. They are split into chunks of
  // that order; each chunk keeps its pieces and how many each candidate gave, and the pieces are put back
  // in candidate order at the end, so the result depends neither on the order nor on the number of threads.
  auto examine = [&](std::uint32_t begin, std::uint32_t end) {
    Examined run;
    const std::uint32_t n = end - begin;
    run.order.resize(n);
    if (grid->empty()) {
      for (std::uint32_t i = 0; i < n; ++i) run.order[i] = begin + i;
    } else {
      std::vector<std::uint32_t> start(grid->cell_count() + 1, 0), cell(n);
      for (std::uint32_t i = 0; i < n; ++i) {
        const Candidate& c = setup.candidates[begin + i];
        cell[i] = static_cast<std::uint32_t>(grid->cell_of(lerp(c.pic0, c.pic1, 0.5)));
        ++start[cell[i] + 1];
      }
      for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
      for (std::uint32_t i = 0; i < n; ++i) run.order[start[cell[i]]++] = begin + i;
    }
    run.chunks.resize((n + Examined::kChunk - 1) / Examined::kChunk);
    constexpr std::uint32_t kAhead = 4;
    // About 0.5 µs per candidate on one core: a thousand of them is half a millisecond.
    parallel_chunks(run.chunks.size(), threads_for(n, 2048, options.threads), [&](std::size_t k) {
      check_cancel();
      Worker& w = workers.local();
      // Each chunk's pieces are gathered in the worker's buffer and stored at their exact size: growing
      // every chunk's vector by doubling would hold up to twice the output in slack at the frame's peak.
      std::vector<VisibleSegment>& buffer = w.buffer;
      buffer.clear();
      Examined::Chunk& chunk = run.chunks[k];
      const auto first = static_cast<std::uint32_t>(k) * Examined::kChunk;
      const std::uint32_t last = std::min(n, first + Examined::kChunk);
      chunk.counts.reserve(last - first);
      for (std::uint32_t i = first; i < last; ++i) {
        const std::size_t before = buffer.size();
        // The candidates come from all over their list: fetch a few ahead, as their order is known.
        if (i + kAhead < last) {
          const Candidate* ahead = &setup.candidates[run.order[i + kAhead]];
          __builtin_prefetch(ahead);
          __builtin_prefetch(reinterpret_cast<const char*>(ahead) + 64);
        }
        w.process(run.order[i], buffer);
        chunk.counts.push_back(static_cast<std::uint32_t>(buffer.size() - before));
      }
      chunk.pieces.assign(buffer.begin(), buffer.end());
    });
    return run;
  };
  std::vector<Examined> runs;
  runs.push_back(examine(0, static_cast<std::uint32_t>(edges)));
  check_cancel();
  ms.examine = lap();

  if (options.intersection_lines) {
    search.wait();
    ms.self_crossings += lap();
    auto guessed_wrong = [&] {
      for (std::size_t o = 0; o < scene.objects.size(); ++o)
        if (setup.cull[o] && !scene.objects[o].solid->self_crossings().empty()) return true;
      return false;
    };
    if (guess && guessed_wrong()) {
      workers.clear();  // their stamps are as many as the occluders culling left
      runs.clear();
      prepare(false);
      runs.push_back(examine(0, static_cast<std::uint32_t>(edges)));
      check_cancel();
      ms.examine += lap();
    }
    append_intersection_candidates(setup, scene, camera, options.include_hidden);
    Rect2 wider = domain;
    const std::size_t end = clip_candidates(setup, edges, camera, wider, options.threads);
    if (end > edges) {
      // The grid holds only the occluders that meet its domain: lines beyond it need a wider grid.
      if (!domain.contains({wider.xmin, wider.ymin}) || !domain.contains({wider.xmax, wider.ymax})) {
        grid = std::make_unique<const FaceGrid>(setup, wider, options.threads);
        for (Worker& w : workers) w.grid = grid.get();
      }
      runs.push_back(examine(static_cast<std::uint32_t>(edges), static_cast<std::uint32_t>(end)));
    }
  }

  FrameResult result;
  const auto n = static_cast<std::uint32_t>(setup.candidates.size());
  result.stats.candidate_edges = n;
  result.stats.occluder_faces = setup.occluders.size();
  result.stats.intersection_lines = n - edges;
  std::size_t face_tests = 0;
  for (const Worker& w : workers) face_tests += w.face_tests;
  // The inputs are no longer needed; free them before the join, which briefly holds the output twice.
  grid.reset();
  setup = FrameSetup{};
  result.segments = in_candidate_order(runs, n, options.threads);
  if (options.coincident_once) remove_covered_pieces(result.segments, options.threads);
  result.stats.face_tests = face_tests;
  ms.finish = lap();
  result.stats.ms = ms;
  result.stats.visible_segments = static_cast<std::size_t>(std::count_if(
      result.segments.begin(), result.segments.end(), [](const VisibleSegment& s) { return !s.hidden; }));
  return result;
}

}  // namespace hlr
