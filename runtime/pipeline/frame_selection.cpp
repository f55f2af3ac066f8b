#include "runtime/pipeline/frame_selection.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <set>
#include <string_view>

#include "runtime/base/limits.hpp"
#include "runtime/pipeline/run_error.hpp"

namespace hlr::runtime {

namespace {

// A whole number 0..kMaxFrames filling `text` exactly.
std::optional<int> parse_count(std::string_view text) {
  int value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || value < 0 ||
      value > static_cast<int>(kMaxFrames))
    return std::nullopt;
  return value;
}

// "A-B", "A" or "A-".
std::optional<FrameRange> parse_item(std::string_view item) {
  const std::size_t dash = item.find('-');
  const auto first = parse_count(item.substr(0, dash));
  if (!first) return std::nullopt;
  if (dash == std::string_view::npos) return FrameRange{*first, *first};
  if (dash + 1 == item.size()) return FrameRange{*first, std::nullopt};
  const auto last = parse_count(item.substr(dash + 1));
  if (!last || *last < *first) return std::nullopt;
  return FrameRange{*first, *last};
}

std::optional<int> env_count(const Environment& env, const char* name) {
  const char* value = env(name);
  return value ? parse_count(value) : std::nullopt;
}

// K and N of a Slurm job array: task ids MIN, MIN + STEP, ..., MAX (sbatch --array=MIN-MAX:STEP).
std::optional<Shard> slurm_shard(const Environment& env, std::string& error) {
  const std::optional<int> id = env_count(env, "SLURM_ARRAY_TASK_ID");
  if (!id) {
    error =
        "--shard auto: SLURM_ARRAY_TASK_ID is not set; run it in an sbatch --array job, or use --shard "
        "auto/N under GNU parallel or a Kubernetes indexed Job, or --shard K/N";
    return std::nullopt;
  }
  const int min = env_count(env, "SLURM_ARRAY_TASK_MIN").value_or(0);
  const int step = std::max(1, env_count(env, "SLURM_ARRAY_TASK_STEP").value_or(1));
  std::optional<int> count = env_count(env, "SLURM_ARRAY_TASK_COUNT");
  if (const std::optional<int> max = env_count(env, "SLURM_ARRAY_TASK_MAX"); max && *max >= min)
    count = (*max - min) / step + 1;
  if (!count || *id < min || (*id - min) % step != 0 || (*id - min) / step >= *count) {
    error = "--shard auto: SLURM_ARRAY_TASK_ID " + std::to_string(*id) +
            " is not one of the array's tasks (SLURM_ARRAY_TASK_MIN/_MAX/_STEP or _COUNT); use a plain range "
            "such as --array=1-8, or --shard K/N";
    return std::nullopt;
  }
  return Shard{(*id - min) / step + 1, *count};
}

// K of N from a Kubernetes indexed Job (0-based) or GNU parallel's job sequence number (1-based).
std::optional<Shard> indexed_shard(const Environment& env, int count, std::string& error) {
  std::optional<int> k;
  std::string from;
  if (const std::optional<int> index = env_count(env, "JOB_COMPLETION_INDEX")) {
    k = *index + 1;
    from = "JOB_COMPLETION_INDEX " + std::to_string(*index);
  } else if (const std::optional<int> seq = env_count(env, "PARALLEL_SEQ")) {
    k = *seq;
    from = "PARALLEL_SEQ " + std::to_string(*seq);
  }
  if (!k) {
    error =
        "--shard auto/" + std::to_string(count) +
        ": neither JOB_COMPLETION_INDEX (a Kubernetes indexed Job) nor PARALLEL_SEQ (GNU parallel) is set";
    return std::nullopt;
  }
  if (*k < 1 || *k > count) {
    error = "--shard auto/" + std::to_string(count) + ": " + from + " is not one of " +
            std::to_string(count) + " jobs";
    return std::nullopt;
  }
  return Shard{*k, count};
}

}  // namespace

const char* process_environment(const char* name) { return std::getenv(name); }

std::optional<FrameList> parse_frame_list(const std::string& text, std::string& error) {
  FrameList list;
  std::string_view rest = text;
  for (;;) {
    const std::size_t comma = rest.find(',');
    const std::optional<FrameRange> item = parse_item(rest.substr(0, comma));
    if (!item) {
      error = "--frames " + text +
              ": expected frame numbers 0 <= A <= B as A-B, A, A- (to the end) or a list of them, e.g. "
              "--frames 0-47 or --frames 0,5,10-20";
      return std::nullopt;
    }
    list.push_back(*item);
    if (comma == std::string_view::npos) return list;
    rest = rest.substr(comma + 1);
  }
}

std::optional<Shard> parse_shard(const std::string& text, std::string& error, const Environment& env) {
  if (text == "auto") return slurm_shard(env, error);
  const std::size_t slash = text.find('/');
  const std::string_view head = std::string_view(text).substr(0, slash);
  const auto n =
      slash == std::string::npos ? std::nullopt : parse_count(std::string_view(text).substr(slash + 1));
  if (head == "auto" && n && *n >= 1) return indexed_shard(env, *n, error);
  const auto k = slash == std::string::npos ? std::nullopt : parse_count(head);
  if (!k || !n || *k < 1 || *k > *n) {
    error = "--shard " + text +
            ": expected K/N with 1 <= K <= N (--shard 3/8: the third of 8 jobs), auto (a Slurm job array) or "
            "auto/N (a Kubernetes indexed Job or GNU parallel)";
    return std::nullopt;
  }
  return Shard{*k, *n};
}

std::vector<int> select_frames(int frame_count, const std::optional<FrameList>& list,
                               const std::optional<Shard>& shard) {
  const int last = frame_count - 1;
  std::set<int> chosen;
  for (const FrameRange& r : list ? *list : FrameList{{0, last}}) {
    if (r.first > last)
      throw RunError("--frames: frame " + std::to_string(r.first) + " is past the end: the script has " +
                         std::to_string(frame_count) +
                         (frame_count == 1 ? " frame (0)" : " frames (0-" + std::to_string(last) + ")"),
                     "choose frames within the animation", 64);
    for (int f = r.first; f <= std::min(last, r.last.value_or(last)); ++f) chosen.insert(f);
  }
  std::vector<int> frames;
  for (int f : chosen)
    if (!shard || f % shard->count == shard->index - 1) frames.push_back(f);
  return frames;
}

}  // namespace hlr::runtime
