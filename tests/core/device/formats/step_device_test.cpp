// The incremental-plotter tape: decoded here independently (position, pen state) and compared with the
// thesis's move strings (reference/004_penup.md §7) and with the strokes' snapped points.
#include "core/device/formats/step_device.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/device/page/atomic_file.hpp"

namespace hlr {
namespace {

struct Decoded {
  std::string instructions;        // header and separators removed
  std::vector<std::string> drawn;  // the direction codes of each pen-down run
  std::vector<std::pair<long, long>> pen_down_at;
  long x = 0, y = 0;
  bool down = false, stopped = false;
};

Decoded decode(const std::string& tape) {
  Decoded d;
  std::size_t pos = 0;
  while (pos < tape.size() && tape[pos] == '#') pos = tape.find('\n', pos) + 1;
  for (; pos < tape.size(); ++pos) {
    const char c = tape[pos];
    if (c == ' ' || c == '\n') continue;
    d.instructions.push_back(c);
  }
  static constexpr int dx[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  static constexpr int dy[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  for (const char c : d.instructions) {
    if (d.stopped) {  // only the "do nothing" padding may follow the stop
      EXPECT_EQ(c, '0') << "instruction after stop";
      continue;
    }
    if (c >= '1' && c <= '8') {
      d.x += dx[c - '1'];
      d.y += dy[c - '1'];
      if (d.down) d.drawn.back().push_back(c);
    } else if (c == 'D') {
      d.down = true;
      d.drawn.emplace_back();
      d.pen_down_at.emplace_back(d.x, d.y);
    } else if (c == 'U') {
      d.down = false;
    } else if (c == 'S') {
      d.stopped = true;
    } else {
      EXPECT_EQ(c, '0') << "unknown instruction";
    }
  }
  return d;
}

PlotPage page_10mm(std::vector<std::vector<Point2>> strokes) {
  PlotPage page;
  page.width_mm = 30;
  page.height_mm = 20;
  for (auto& points : strokes) page.strokes.push_back({std::move(points), 1, StrokeLayer::Visible});
  return page;
}

TEST(StepDevice, ThesisMoveStringsBothWays) {
  StepOptions o;
  o.step_mm = 1;
  // Grid (0,0) is the page's bottom-left corner: page y = 20 − grid y.
  const Decoded fwd = decode(to_plotter_steps(page_10mm({{{0, 20}, {2, 19}}}), o));
  ASSERT_EQ(fwd.drawn.size(), 1U);
  EXPECT_EQ(fwd.drawn[0], "23");
  const Decoded back = decode(to_plotter_steps(page_10mm({{{2, 19}, {0, 20}}}), o));
  EXPECT_EQ(back.drawn[0], "76");
  const Decoded long_fwd = decode(to_plotter_steps(page_10mm({{{0, 20}, {14, 11}}}), o));
  EXPECT_EQ(long_fwd.drawn[0], "23223223232232");
  const Decoded long_back = decode(to_plotter_steps(page_10mm({{{14, 11}, {0, 20}}}), o));
  EXPECT_EQ(long_back.drawn[0], "67667676676676");
}

TEST(StepDevice, TapeVisitsEveryStrokeAndReturnsHome) {
  StepOptions o;  // 0.1 mm
  const PlotPage page = page_10mm({{{5, 5}, {12.34, 7.5}, {20, 15}}, {{25, 2}, {3, 18}}});
  StepCounts counts;
  const std::string tape = to_plotter_steps(page, o, &counts);
  const Decoded d = decode(tape);
  EXPECT_TRUE(d.stopped);
  EXPECT_FALSE(d.down);
  EXPECT_EQ(d.x, 0);
  EXPECT_EQ(d.y, 0);
  ASSERT_EQ(d.pen_down_at.size(), 2U);
  EXPECT_EQ(d.pen_down_at[0], (std::pair<long, long>{50, 150}));
  EXPECT_EQ(d.pen_down_at[1], (std::pair<long, long>{250, 180}));
  // Pen-down steps: max(|dx|, |dy|) per segment, in grid steps.
  EXPECT_EQ(d.drawn[0].size(), 73U + 77U);  // (50,150)→(123,125): 73; →(200,50): 77 in x, 75 in y
  EXPECT_EQ(d.drawn[1].size(), 220U);
  EXPECT_EQ(counts.pen_down_steps, 73U + 77U + 220U);
  EXPECT_EQ(counts.lifts, 2U);
  // Three "do nothing" after every pen instruction, rows of two.
  for (std::size_t i = 0; i < d.instructions.size(); ++i) {
    if (d.instructions[i] == 'U' || d.instructions[i] == 'D' || d.instructions[i] == 'S') {
      EXPECT_EQ(d.instructions.substr(i + 1, 3), "000");
    }
  }
  EXPECT_EQ(d.instructions.size() % 2, 0U);
}

TEST(StepDevice, ErrorsAreClear) {
  StepOptions o;
  EXPECT_THROW(to_plotter_steps(page_10mm({{{-1, 5}, {3, 3}}}), o), DeviceError);
  EXPECT_THROW(to_plotter_steps(page_10mm({{{1, 5}, {3, 300}}}), o), DeviceError);
  o.step_mm = 0;
  EXPECT_THROW(to_plotter_steps(page_10mm({{{1, 5}, {3, 3}}}), o), DeviceError);
  try {
    to_plotter_steps(page_10mm({{{1, 5}, {31, 3}}}), StepOptions{});
    FAIL();
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("off the 30 x 20 mm sheet"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hlr
