// Which frames a run renders: --frames A-B (frame numbers, 0-based, inclusive) and --shard K/N (of those,
// the frames f with f % N == K − 1). Both depend on frame numbers only, so N machines given K = 1..N
// render disjoint sets that together are the whole selection, whatever their order or speed.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hlr::runtime {

struct FrameRange {
  int first = 0;
  int last = 0;  // inclusive
};

struct Shard {
  int index = 1;  // K, 1-based
  int count = 1;  // N
};

// "12-47" or "12". Returns nullopt and sets `error` for anything else.
std::optional<FrameRange> parse_frame_range(const std::string& text, std::string& error);
// "3/8". Returns nullopt and sets `error` unless 1 ≤ K ≤ N.
std::optional<Shard> parse_shard(const std::string& text, std::string& error);

// The selected frame numbers in increasing order. Throws RunError (exit 64) when the range starts past
// the last frame; a range ending past it is cut at the last frame.
std::vector<int> select_frames(int frame_count, const std::optional<FrameRange>& range,
                               const std::optional<Shard>& shard);

}  // namespace hlr::runtime
