// The incremental plotter's eight-direction stepping with the Knight's Move tie-break
// (reference/004_penup.md §7): the thesis's two lines, exact reversal, end points, deviation.
#include "core/plan/plotter_stepping.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace hlr {
namespace {

std::string reversed_path(const std::string& steps) {
  std::string r(steps.rbegin(), steps.rend());
  for (char& c : r) c = opposite_plotter_step(c);
  return r;
}

TEST(PlotterStepping, DirectionCodes) {
  const GridPoint o{0, 0};
  EXPECT_EQ(plotter_steps(o, {0, 3}), "111");
  EXPECT_EQ(plotter_steps(o, {2, 2}), "22");
  EXPECT_EQ(plotter_steps(o, {3, 0}), "333");
  EXPECT_EQ(plotter_steps(o, {2, -2}), "44");
  EXPECT_EQ(plotter_steps(o, {0, -1}), "5");
  EXPECT_EQ(plotter_steps(o, {-1, -1}), "6");
  EXPECT_EQ(plotter_steps(o, {-2, 0}), "77");
  EXPECT_EQ(plotter_steps(o, {-1, 1}), "8");
  EXPECT_EQ(plotter_steps(o, o), "");
  EXPECT_EQ(opposite_plotter_step('1'), '5');
  EXPECT_EQ(opposite_plotter_step('2'), '6');
  EXPECT_EQ(opposite_plotter_step('8'), '4');
}

// Figure 2: (0,0)→(2,1) — at the start δs = +1, δd = −1, a tie; B is true, so the diagonal first.
TEST(PlotterStepping, ThesisTwoOne) {
  EXPECT_EQ(plotter_steps({0, 0}, {2, 1}), "23");
  EXPECT_EQ(plotter_steps({2, 1}, {0, 0}), "76");
  EXPECT_EQ(reversed_path(plotter_steps({2, 1}, {0, 0})), "23");
  // Without the correction both directions take the diagonal first, and the paths diverge (Diagram 1.8).
  EXPECT_EQ(plotter_steps({0, 0}, {2, 1}, false), "23");
  EXPECT_EQ(plotter_steps({2, 1}, {0, 0}, false), "67");
  EXPECT_NE(reversed_path(plotter_steps({2, 1}, {0, 0}, false)), "23");
}

// Figure 1: (0,0)→(14,9).
TEST(PlotterStepping, ThesisFourteenNine) {
  EXPECT_EQ(plotter_steps({0, 0}, {14, 9}), "23223223232232");
  EXPECT_EQ(plotter_steps({14, 9}, {0, 0}), "67667676676676");
  EXPECT_EQ(reversed_path(plotter_steps({14, 9}, {0, 0})), plotter_steps({0, 0}, {14, 9}));
}

// Every ordered pair of distinct mesh points in [−12, 12]²: the steps end at B, A→B is B→A reversed,
// and no step strays half a unit or more from the true line. The uncorrected procedure diverges on many.
TEST(PlotterStepping, ReversibleOnAllPairs) {
  constexpr int R = 12;
  int pairs = 0, diverging_uncorrected = 0;
  double worst = 0;
  for (int ax = -R; ax <= R; ++ax)
    for (int ay = -R; ay <= R; ++ay)
      for (int bx = -R; bx <= R; ++bx)
        for (int by = -R; by <= R; ++by) {
          const GridPoint a{ax, ay}, b{bx, by};
          if (a == b) continue;
          ++pairs;
          const std::string f = plotter_steps(a, b), r = plotter_steps(b, a);
          ASSERT_EQ(f.size(), static_cast<std::size_t>(std::max(std::abs(bx - ax), std::abs(by - ay))));
          ASSERT_EQ(apply_plotter_steps(a, f), b) << ax << "," << ay << " → " << bx << "," << by;
          ASSERT_EQ(reversed_path(r), f) << ax << "," << ay << " → " << bx << "," << by;
          if (reversed_path(plotter_steps(b, a, false)) != plotter_steps(a, b, false)) ++diverging_uncorrected;
          // Perpendicular distance of every visited point from the line AB.
          const double len = std::hypot(bx - ax, by - ay);
          GridPoint p = a;
          for (char c : f) {
            p = apply_plotter_steps(p, std::string(1, c));
            const double dev = std::fabs(static_cast<double>((p.y - ay) * (bx - ax) - (by - ay) * (p.x - ax))) / len;
            worst = std::max(worst, dev);
          }
        }
  EXPECT_EQ(pairs, 390000);
  EXPECT_LT(worst, 0.5);
  EXPECT_EQ(diverging_uncorrected, 128208);  // reference/004_penup.md §7
}

TEST(PlotterStepping, RejectsBadCodes) {
  EXPECT_THROW(apply_plotter_steps({0, 0}, "9"), std::invalid_argument);
  EXPECT_THROW(opposite_plotter_step('0'), std::invalid_argument);
}

}  // namespace
}  // namespace hlr
