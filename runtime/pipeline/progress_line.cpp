#include "runtime/pipeline/progress_line.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace hlr::runtime {

namespace {
constexpr std::chrono::milliseconds kQuietStart{1000};  // runs shorter than this show nothing
constexpr std::chrono::milliseconds kRedraw{100};       // at most ten redraws a second
constexpr const char* kEraseLine = "\r\x1b[K";
}  // namespace

std::string progress_text(std::size_t done, std::size_t total, double seconds) {
  char line[128];
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
  const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0;
  std::snprintf(line, sizeof line, "frame %zu/%zu, %.1f frames/s, %.0f s left", done, total, rate,
                std::ceil(left));
  return line;
}

void ProgressLine::update(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  if (now - start_ < kQuietStart || (shown_ && now - last_ < kRedraw && done < total)) return;
  last_ = now;
  shown_ = true;
  out_ << kEraseLine
       << "hlrscript: " << progress_text(done, total, std::chrono::duration<double>(now - start_).count())
       << std::flush;
}

void ProgressLine::clear() {
  if (!shown_) return;
  out_ << kEraseLine << std::flush;
  shown_ = false;
}

}  // namespace hlr::runtime
