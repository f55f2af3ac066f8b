// The one-line progress display of a long run, on a terminal's stderr: frames done of the total, frames
// per second and the time left, redrawn in place at most ten times a second and only once the run has
// taken a second (short runs print nothing). Erased when the run ends.
#pragma once

#include <chrono>
#include <cstddef>
#include <ostream>

namespace hlr::runtime {

class ProgressLine {
 public:
  ProgressLine(std::ostream& out, bool enabled) : out_(out), enabled_(enabled) {}
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(std::size_t done, std::size_t total);
  void clear();  // erases the line, if one is shown

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& out_;
  bool enabled_;
  bool shown_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_{};
};

// "frame 12/48, 8.3 frames/s, 4 s left": the text of the line (tests).
std::string progress_text(std::size_t done, std::size_t total, double seconds);

}  // namespace hlr::runtime
