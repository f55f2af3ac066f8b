// The one scheduler: oneTBB. Frames (runtime/pipeline/frame_pipeline.cpp) and the work inside a frame (the
// engine's objects and edges) are tasks of the same arena, so idle cores steal whatever is left, and the
// arena the caller runs in (hlrscript --jobs N) bounds them all.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>

namespace hlr {

// Work below about a millisecond is done on the calling thread: waking the scheduler's threads (the
// first time, starting them) costs more than sharing it out saves. `items` counts what the caller's
// unit of work is (candidate edges, faces); `min_items` is how many of them make a millisecond.
inline unsigned threads_for(std::size_t items, std::size_t min_items, unsigned threads) {
  return items < min_items ? 1 : threads;
}

// Calls body(k) once for every k in [0, count), in parallel. threads: 1 runs them in order on this
// thread; 0 shares the caller's arena (every core, or what `--jobs` allows); N > 1 runs them in an arena
// of N threads. Results must not depend on which thread ran which k: callers write into slot k.
template <typename Body>
void parallel_chunks(std::size_t count, unsigned threads, const Body& body) {
  if (threads == 1 || count <= 1) {
    for (std::size_t k = 0; k < count; ++k) body(k);
    return;
  }
  auto run = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t k = r.begin(); k != r.end(); ++k) body(k);
                      });
  };
  if (threads == 0) {
    run();
  } else {
    tbb::task_arena arena(static_cast<int>(threads));
    arena.execute(run);
  }
}

// Calls body(i) once for every i in [0, count), by parts of `part` indices side by side (on the calling
// thread below two parts' worth, as threads_for). A body that gathers a per-part result should use
// parallel_chunks instead, and store it once: parts' results side by side share cache lines.
template <typename Body>
void parallel_indices(std::size_t count, std::size_t part, const Body& body) {
  parallel_chunks((count + part - 1) / part, threads_for(count, 2 * part, 0), [&](std::size_t k) {
    for (std::size_t i = k * part; i < std::min(count, (k + 1) * part); ++i) body(i);
  });
}

}  // namespace hlr
