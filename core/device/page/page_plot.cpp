#include "core/device/page/page_plot.hpp"

#include <algorithm>
#include <cmath>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/sheet_layout.hpp"
#include "core/device/page/stroke_text.hpp"
#include "core/limits.hpp"
#include "core/plan/hidden_precedence.hpp"

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

// Text strokes as pieces of one pen, visible.
void add_strokes(const std::vector<std::vector<Point2>>& strokes, int pen, std::vector<PlotPiece>& pieces) {
  for (const std::vector<Point2>& stroke : strokes)
    for (std::size_t i = 1; i < stroke.size(); ++i) {
      PlotPiece p;
      p.a = stroke[i - 1];
      p.b = stroke[i];
      p.pen = pen;
      pieces.push_back(p);
    }
}

// The caption's strokes as pieces of pen 1: on the baseline where the printed caption sits (0.6 of the
// margin up from the bottom edge) unless the pen cannot reach its descenders there, then raised to the
// reach; made smaller when the band between the drawing and the reach, or the page's width, is too small.
void add_caption(const std::string& caption, const PlotPage& page, double reach,
                 std::vector<PlotPiece>& pieces) {
  const double margin = page.margin_mm, descent_per_cap = 7.0 / 21.0;
  const double band = margin - reach - 1;  // from the reach's edge to 1 mm below the drawing
  double cap = std::min(kCaptionCapHeightMm, band / (1 + descent_per_cap));
  const double left = std::max(margin, reach), room = page.width_mm - 2 * left;
  const double width = stroke_text_width_mm(caption, cap);
  if (width > room && width > 0) cap *= room / width;
  if (!(cap > 0.5)) return;  // no room for legible letters: no caption
  const double baseline =
      std::min(page.height_mm - 0.6 * margin, page.height_mm - reach - cap * descent_per_cap);
  add_strokes(stroke_text(caption, {left, baseline}, cap), 1, pieces);
}

// The pieces of segments [first, end) on the page by `layout`, in their pens and layers; counted in `out`.
void add_segment_pieces(const std::vector<VisibleSegment>& segments, std::size_t first, std::size_t end,
                        const PageLayout& layout, const PagePlotOptions& o, PagePlot& out,
                        std::vector<PlotPiece>& pieces) {
  const int hidden_pen = o.hidden_pen ? checked_pen(*o.hidden_pen) : 0;  // 0: the object's pen
  const bool by_level = o.hidden.counts_levels();
  if (by_level && out.level_pieces.empty())
    out.level_pieces.assign(static_cast<std::size_t>(o.hidden.levels) + 1, 0);
  for (std::size_t i = first; i < end; ++i) {
    const VisibleSegment& s = segments[i];
    if (!s.hidden) ++out.visible_segments;
    if (s.hidden && !o.hidden.drawn()) continue;
    // By level: only the levels asked for (the engine returns no others; a piece without one is not ours).
    const int level = s.hidden && by_level ? s.level : 0;
    if (s.hidden && by_level && (level < 1 || level > o.hidden.levels)) continue;
    const int object_pen = s.object < o.object_pens.size() ? checked_pen(o.object_pens[s.object]) : 1;
    PlotPiece p;
    p.a = page_point(layout, s.s0);
    p.b = page_point(layout, s.s1);
    // Level k in the k-th pen from the hidden pen: each level a pen of its own on a plotter.
    p.pen = s.hidden && hidden_pen > 0 ? checked_pen(hidden_pen + std::max(level, 1) - 1) : object_pen;
    p.layer = s.hidden ? StrokeLayer::Hidden : StrokeLayer::Visible;
    if (s.hatch && !s.hidden) {  // the engine gives no hidden hatch pieces
      const int hatch_pen = s.object < o.hatch_pens.size() ? o.hatch_pens[s.object] : 0;
      if (hatch_pen > 0) p.pen = checked_pen(hatch_pen);
      p.layer = StrokeLayer::Hatch;
    }
    p.level = level;
    if (level > 0) ++out.level_pieces[static_cast<std::size_t>(level)];
    pieces.push_back(p);
  }
}

void add_page_texts(const PagePlotOptions& o, std::vector<PlotPiece>& pieces) {
  for (const PageText& text : o.texts)
    add_strokes(stroke_text(text.text, text.at, text.size_mm), checked_pen(text.pen), pieces);
}

// The plan: the page's strokes and statistics.
void plan_page(std::vector<PlotPiece>& pieces, const PagePlotOptions& o, PagePlot& out) {
  if (o.hidden.drawn()) drop_hidden_under_visible(pieces);
  PenPlan plan = plan_pen_strokes(pieces, o.plan);
  if (o.hidden_dashes && o.hidden.drawn()) dash_hidden_strokes(plan, *o.hidden_dashes, o.plan);
  out.page.strokes = std::move(plan.strokes);
  out.stats = plan.stats;
}

void add_rect(const Rect2& r, std::vector<PlotPiece>& pieces) {
  add_strokes({{{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}, {r.xmin, r.ymin}}}, 1,
              pieces);
}

// Text in a cell of the title block: left-aligned 2 mm in, centred vertically, shrunk to fit its width.
void add_cell_text(const std::string& text, const Rect2& cell, double cap, std::vector<PlotPiece>& pieces) {
  if (text.empty()) return;
  const double room = cell.width() - 4, width = stroke_text_width_mm(text, cap);
  if (width > room && width > 0) cap *= room / width;
  if (!(cap > 0.5)) return;
  add_strokes(stroke_text(text, {cell.xmin + 2, 0.5 * (cell.ymin + cell.ymax) + 0.5 * cap}, cap), 1, pieces);
}

}  // namespace

PagePlot plot_page(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                   std::string caption, const PagePlotOptions& o) {
  PagePlot out;
  out.layout = o.extent ? fit_rect_to_page(*o.extent, o.spec) : fit_to_page(frame, segments, o.spec);
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
  std::vector<PlotPiece> pieces;
  pieces.reserve(segments.size());
  add_segment_pieces(segments, 0, segments.size(), out.layout, o, out, pieces);
  add_page_texts(o, pieces);
  if (o.caption_as_strokes && !out.page.caption.empty()) {
    add_caption(out.page.caption, out.page, o.reach_margin_mm, pieces);
    out.page.caption.clear();  // drawn: no device prints it again
  }
  plan_page(pieces, o, out);
  return out;
}

PagePlot plot_sheet(const std::vector<VisibleSegment>& segments, const std::vector<SheetView>& views,
                    const SheetTitle& title, const PagePlotOptions& o) {
  PagePlot out;
  out.page.width_mm = o.spec.paper.width_mm;
  out.page.height_mm = o.spec.paper.height_mm;
  out.page.margin_mm = o.spec.margin_mm;
  if (!views.empty()) out.layout = views.front().layout;
  std::vector<PlotPiece> pieces;
  pieces.reserve(segments.size());
  // Dimensions first: each view's label goes under its drawing and its dimensions both.
  std::vector<DimensionDrawing> dimensions;
  for (const PageDimension& d : o.dimensions) {
    dimensions.push_back(d.view < views.size()
                             ? dimension_strokes(d, views[d.view].camera, views[d.view].layout)
                             : DimensionDrawing{{}, 0, {}, "its view is not on the sheet"});
    out.dimension_problems.push_back(dimensions.back().problem);
  }
  for (std::size_t v = 0; v < views.size(); ++v) {
    const SheetView& view = views[v];
    const std::size_t before = pieces.size();
    add_segment_pieces(segments, view.first_segment, view.end_segment, view.layout, o, out, pieces);
    Rect2 box = Rect2::none();
    if (const std::optional<Rect2>& f = view.camera.frame) {
      box.include(page_point(view.layout, {f->xmin, f->ymin}));
      box.include(page_point(view.layout, {f->xmax, f->ymax}));
    } else {
      for (std::size_t i = before; i < pieces.size(); ++i) {
        box.include(pieces[i].a);
        box.include(pieces[i].b);
      }
    }
    for (std::size_t k = 0; k < o.dimensions.size(); ++k) {
      if (o.dimensions[k].view != v) continue;
      add_strokes(dimensions[k].strokes, checked_pen(o.dimensions[k].pen), pieces);
      for (const std::vector<Point2>& stroke : dimensions[k].strokes)
        for (const Point2& p : stroke) box.include(p);
    }
    if (!view.label.empty() && !box.empty()) {
      const double width = stroke_text_width_mm(view.label, kViewLabelCapMm);
      const Point2 at{0.5 * (box.xmin + box.xmax) - 0.5 * width,
                      box.ymax + kViewLabelGapMm + kViewLabelCapMm};
      add_strokes(stroke_text(view.label, at, kViewLabelCapMm), 1, pieces);
      box.include({at.x, at.y + kViewLabelCapMm * kStrokeTextDescent});
      box.include({at.x + width, at.y});
    }
    out.view_boxes.push_back(box);
  }
  add_page_texts(o, pieces);
  if (title.framed) {
    const SheetFrame sheet = sheet_frame(o.spec);
    add_rect(sheet.frame, pieces);
    if (const Rect2& b = sheet.title_block; !b.empty()) {
      add_rect(b, pieces);
      const double mid = 0.5 * (b.ymin + b.ymax);
      add_strokes({{{b.xmin, mid}, {b.xmax, mid}}}, 1, pieces);
      add_cell_text(title.title, {b.xmin, b.ymin, b.xmax, mid}, 3.5, pieces);
      add_cell_text(title.scale.empty() ? "" : "SCALE " + title.scale, {b.xmin, mid, b.xmax, b.ymax}, 2.5,
                    pieces);
    }
  }
  plan_page(pieces, o, out);
  return out;
}

}  // namespace hlr
