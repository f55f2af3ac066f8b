// Visible lines over hidden ones: hidden pieces lying on visible ones give way, worked out by hand.
#include "core/plan/hidden_precedence.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace hlr {
namespace {

PlotPiece piece(Point2 a, Point2 b, StrokeLayer layer = StrokeLayer::Visible, int level = 0) {
  PlotPiece p;
  p.a = a;
  p.b = b;
  p.layer = layer;
  p.level = level;
  return p;
}

double hidden_length(const std::vector<PlotPiece>& pieces, int level = -1) {
  double sum = 0;
  for (const PlotPiece& p : pieces)
    if (p.layer == StrokeLayer::Hidden && (level < 0 || p.level == level)) sum += distance(p.a, p.b);
  return sum;
}

TEST(HiddenPrecedence, AHiddenPieceUnderAVisibleOneIsNotDrawn) {
  // The plan view of a box: the bottom's edges lie under the top's, in the other direction and split
  // elsewhere.
  std::vector<PlotPiece> pieces{
      piece({0, 0}, {10, 0}), piece({10, 0}, {10, 5}), piece({10, 0}, {4, 0}, StrokeLayer::Hidden),
      piece({4, 0}, {0, 0}, StrokeLayer::Hidden), piece({10, 5}, {10, 0}, StrokeLayer::Hidden)};
  EXPECT_EQ(drop_hidden_under_visible(pieces), 3U);
  EXPECT_EQ(pieces.size(), 2U);
  EXPECT_EQ(hidden_length(pieces), 0);
}

TEST(HiddenPrecedence, APartlyCoveredPieceKeepsWhatIsUncovered) {
  // Hidden from 0 to 20 on y = 1; visible over [3, 7] and [6, 12]: hidden [0, 3] and [12, 20] remain.
  std::vector<PlotPiece> pieces{piece({0, 1}, {20, 1}, StrokeLayer::Hidden), piece({3, 1}, {7, 1}),
                                piece({12, 1}, {6, 1})};
  EXPECT_EQ(drop_hidden_under_visible(pieces), 1U);
  std::vector<std::pair<double, double>> kept;
  for (const PlotPiece& p : pieces)
    if (p.layer == StrokeLayer::Hidden) kept.emplace_back(std::min(p.a.x, p.b.x), std::max(p.a.x, p.b.x));
  std::sort(kept.begin(), kept.end());
  ASSERT_EQ(kept.size(), 2U);
  EXPECT_DOUBLE_EQ(kept[0].first, 0);
  EXPECT_NEAR(kept[0].second, 3, 1e-12);
  EXPECT_NEAR(kept[1].first, 12, 1e-12);
  EXPECT_DOUBLE_EQ(kept[1].second, 20);
  // The kept parts stay where the hidden piece was in the order: first.
  EXPECT_EQ(pieces[0].layer, StrokeLayer::Hidden);
}

TEST(HiddenPrecedence, OnlyPiecesOnTheSameLineCover) {
  // Parallel 0.01 mm away (ten times the tolerance), crossing, and at a slight angle: all stay.
  std::vector<PlotPiece> pieces{piece({0, 0}, {10, 0}, StrokeLayer::Hidden), piece({0, 0.01}, {10, 0.01}),
                                piece({5, -3}, {5, 3}), piece({0, 0}, {10, 0.05})};
  EXPECT_EQ(drop_hidden_under_visible(pieces), 0U);
  EXPECT_DOUBLE_EQ(hidden_length(pieces), 10);
  // Within the tolerance: covered.
  std::vector<PlotPiece> near{piece({0, 0}, {10, 0}, StrokeLayer::Hidden), piece({-1, 0.0005}, {11, 0.0005})};
  drop_hidden_under_visible(near);
  EXPECT_EQ(hidden_length(near), 0);
}

TEST(HiddenPrecedence, ALongHiddenPieceUnderAShortVisibleOneOnlyLosesThatPart) {
  std::vector<PlotPiece> pieces{piece({0, 0}, {100, 100}, StrokeLayer::Hidden), piece({50, 50}, {51, 51})};
  drop_hidden_under_visible(pieces);
  EXPECT_NEAR(hidden_length(pieces), (100 - 1) * std::sqrt(2.0), 1e-9);
}

TEST(HiddenPrecedence, ByLevelTheShallowerWins) {
  // Levels 1, 2 and 3 on one line, each over a different stretch of [0, 9].
  std::vector<PlotPiece> pieces{piece({0, 0}, {9, 0}, StrokeLayer::Hidden, 3),
                                piece({0, 0}, {6, 0}, StrokeLayer::Hidden, 2),
                                piece({0, 0}, {3, 0}, StrokeLayer::Hidden, 1)};
  drop_hidden_under_visible(pieces);
  EXPECT_NEAR(hidden_length(pieces, 1), 3, 1e-12);
  EXPECT_NEAR(hidden_length(pieces, 2), 3, 1e-12);
  EXPECT_NEAR(hidden_length(pieces, 3), 3, 1e-12);
}

TEST(HiddenPrecedence, HiddenPiecesOnOneAnotherAreDrawnOnce) {
  // The front and back edges of a hole seen end on: the earlier is kept, the later loses what it shares.
  std::vector<PlotPiece> pieces{piece({0, 0}, {0, 8}, StrokeLayer::Hidden),
                                piece({0, 10}, {0, 2}, StrokeLayer::Hidden)};
  EXPECT_EQ(drop_hidden_under_visible(pieces), 1U);
  EXPECT_NEAR(hidden_length(pieces), 10, 1e-12);
  ASSERT_EQ(pieces.size(), 2U);
  EXPECT_NEAR(distance(pieces[0].a, pieces[0].b), 8, 1e-12);
}

TEST(HiddenPrecedence, HatchNeitherCoversNorIsCovered) {
  std::vector<PlotPiece> pieces{piece({0, 0}, {10, 0}, StrokeLayer::Hidden),
                                piece({0, 0}, {10, 0}, StrokeLayer::Hatch)};
  EXPECT_EQ(drop_hidden_under_visible(pieces), 0U);
  EXPECT_EQ(pieces.size(), 2U);
}

TEST(HiddenPrecedence, ManyPiecesFarApartAreFoundThroughTheGrid) {
  // 400 visible pieces on a lattice with a hidden twin under every other one.
  std::vector<PlotPiece> pieces;
  int twins = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const Point2 a{i * 10.0, j * 7.0}, b{i * 10.0 + 6, j * 7.0 + 3};
      pieces.push_back(piece(a, b));
      if ((i + j) % 2 == 0) {
        pieces.push_back(piece(b, a, StrokeLayer::Hidden));
        ++twins;
      } else {
        pieces.push_back(piece({a.x, a.y + 1}, {b.x, b.y + 1}, StrokeLayer::Hidden));
      }
    }
  EXPECT_EQ(drop_hidden_under_visible(pieces), static_cast<std::size_t>(twins));
  EXPECT_NEAR(hidden_length(pieces), (400 - twins) * std::sqrt(45.0), 1e-9);
}

}  // namespace
}  // namespace hlr
