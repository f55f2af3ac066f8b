#include "core/device/page_plot.hpp"

#include "core/limits.hpp"

#include <cmath>

#include "core/device/atomic_file.hpp"

namespace hlr {
namespace {

Point2 page_point(const PageLayout& layout, Point2 picture) {
  const Point2 mm = layout.to_page_mm(picture);
  if (!std::isfinite(mm.x) || !std::isfinite(mm.y))
    throw DeviceError("a piece maps to a non-finite page coordinate; cannot draw it");
  return mm;
}

int checked_pen(int pen) {
  if (pen < 1 || pen > kMaxPen)
    throw DeviceError("pen " + std::to_string(pen) + " is outside 1.." + std::to_string(kMaxPen));
  return pen;
}

}  // namespace

PagePlot plot_page(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                   std::string caption, const PagePlotOptions& o) {
  PagePlot out;
  out.layout = fit_to_page(frame, segments, o.spec);
  out.page.width_mm = o.spec.paper.width_mm;
  out.page.height_mm = o.spec.paper.height_mm;
  out.page.margin_mm = o.spec.margin_mm;
  out.page.caption = std::move(caption);
  if (frame) {
    // The layout flips y: the frame's top-left on the page is the picture's (xmin, ymax).
    const Point2 a = page_point(out.layout, {frame->xmin, frame->ymax});
    const Point2 b = page_point(out.layout, {frame->xmax, frame->ymin});
    out.page.border = Rect2{a.x, a.y, b.x, b.y};
  }
  const int hidden_pen = o.hidden_pen ? checked_pen(*o.hidden_pen) : 0;  // 0: the object's pen
  std::vector<PlotPiece> pieces;
  pieces.reserve(segments.size());
  for (const VisibleSegment& s : segments) {
    if (!s.hidden) ++out.visible_segments;
    if (s.hidden && !o.include_hidden) continue;
    const int object_pen = s.object < o.object_pens.size() ? checked_pen(o.object_pens[s.object]) : 1;
    PlotPiece p;
    p.a = page_point(out.layout, s.s0);
    p.b = page_point(out.layout, s.s1);
    p.pen = s.hidden && hidden_pen > 0 ? hidden_pen : object_pen;
    p.layer = s.hidden ? StrokeLayer::Hidden : StrokeLayer::Visible;
    pieces.push_back(p);
  }
  PenPlan plan = plan_pen_strokes(pieces, o.plan);
  out.page.strokes = std::move(plan.strokes);
  out.stats = plan.stats;
  return out;
}

}  // namespace hlr
