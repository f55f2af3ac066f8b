#include "runtime/frame_selection.hpp"

#include <algorithm>
#include <charconv>

#include "runtime/limits.hpp"
#include "runtime/run_error.hpp"

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

}  // namespace

std::optional<FrameRange> parse_frame_range(const std::string& text, std::string& error) {
  const std::size_t dash = text.find('-');
  const auto first = parse_count(std::string_view(text).substr(0, dash));
  const auto last = dash == std::string::npos ? first : parse_count(std::string_view(text).substr(dash + 1));
  if (!first || !last || *last < *first) {
    error = "--frames " + text +
            ": expected A-B with frame numbers 0 <= A <= B (or one frame A), e.g. --frames 0-47";
    return std::nullopt;
  }
  return FrameRange{*first, *last};
}

std::optional<Shard> parse_shard(const std::string& text, std::string& error) {
  const std::size_t slash = text.find('/');
  const auto k =
      slash == std::string::npos ? std::nullopt : parse_count(std::string_view(text).substr(0, slash));
  const auto n =
      slash == std::string::npos ? std::nullopt : parse_count(std::string_view(text).substr(slash + 1));
  if (!k || !n || *k < 1 || *k > *n) {
    error = "--shard " + text + ": expected K/N with 1 <= K <= N, e.g. --shard 3/8 for the third of 8 jobs";
    return std::nullopt;
  }
  return Shard{*k, *n};
}

std::vector<int> select_frames(int frame_count, const std::optional<FrameRange>& range,
                               const std::optional<Shard>& shard) {
  int first = 0, last = frame_count - 1;
  if (range) {
    if (range->first > last)
      throw RunError("--frames " + std::to_string(range->first) + "-" + std::to_string(range->last) +
                         ": the script has " + std::to_string(frame_count) +
                         (frame_count == 1 ? " frame (0)" : " frames (0-" + std::to_string(last) + ")"),
                     "choose frames within the animation", 64);
    first = range->first;
    last = std::min(last, range->last);
  }
  std::vector<int> frames;
  for (int f = first; f <= last; ++f)
    if (!shard || f % shard->count == shard->index - 1) frames.push_back(f);
  return frames;
}

}  // namespace hlr::runtime
