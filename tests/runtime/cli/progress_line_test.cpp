// The progress line's text, and that it stays silent where it must.
#include "runtime/pipeline/progress_line.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace hlr::runtime {
namespace {

TEST(ProgressLine, SaysFramesRateAndTimeLeft) {
  EXPECT_EQ(progress_text(12, 48, 1.5), "frame 12/48, 8.0 frames/s, 5 s left");  // 36 / 8 = 4.5, rounded up
  EXPECT_EQ(progress_text(48, 48, 6), "frame 48/48, 8.0 frames/s, 0 s left");
  EXPECT_EQ(progress_text(0, 10, 0), "frame 0/10, 0.0 frames/s, 0 s left");
}

TEST(ProgressLine, ShortOrDisabledRunsPrintNothing) {
  std::ostringstream out;
  {
    ProgressLine quiet(out, false);
    quiet.update(1, 2);
    ProgressLine shortRun(out, true);  // within its first second: nothing yet
    shortRun.update(1, 2);
  }
  EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace hlr::runtime
