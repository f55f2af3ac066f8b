// Which frames a run renders: --frames LIST (frame numbers, 0-based, as Blender's -f takes them:
// "0-47", "0,5,10-20", "10-" to the end) and --shard K/N (of those, the frames f with f % N == K − 1).
// Both depend on frame numbers only, so N machines given K = 1..N render disjoint sets that together
// are the whole selection, whatever their order or speed. `--shard auto` reads K and N from a Slurm job
// array, `--shard auto/N` reads K from a Kubernetes indexed Job or GNU parallel.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hlr::runtime {

struct FrameRange {
  int first = 0;
  std::optional<int> last;  // inclusive; none: to the last frame ("10-")
};
using FrameList = std::vector<FrameRange>;

struct Shard {
  int index = 1;  // K, 1-based
  int count = 1;  // N
};

// "12-47", "12", "10-" or a comma-separated list of them. Returns nullopt and sets `error` otherwise.
std::optional<FrameList> parse_frame_list(const std::string& text, std::string& error);

// Reads an environment variable; nullptr when unset (std::getenv by default; tests pass their own).
using Environment = std::function<const char*(const char*)>;
const char* process_environment(const char* name);

// "3/8"; "auto": K and N of a Slurm job array (SLURM_ARRAY_TASK_ID with _MIN, _MAX, _STEP or _COUNT);
// "auto/8": K from JOB_COMPLETION_INDEX (0-based, Kubernetes) or PARALLEL_SEQ (1-based, GNU parallel).
// Returns nullopt and sets `error` unless 1 ≤ K ≤ N.
std::optional<Shard> parse_shard(const std::string& text, std::string& error,
                                 const Environment& env = process_environment);

// The selected frame numbers in increasing order, each once. Throws RunError (exit 64) when an item of
// the list starts past the last frame; an item ending past it is cut at the last frame.
std::vector<int> select_frames(int frame_count, const std::optional<FrameList>& list,
                               const std::optional<Shard>& shard);

}  // namespace hlr::runtime
