#include "runtime/pipeline/sheet_render.hpp"

#include <algorithm>
#include <optional>

#include "core/device/page/sheet_layout.hpp"
#include "core/geometry/box3.hpp"
#include "core/tolerance.hpp"
#include "runtime/base/eval_error.hpp"

namespace hlr::runtime {

namespace {

// How far the dimensions drawn in view `v` reach past its drawing (at `scale`, laid out by `layout`).
ViewMargins dimension_margins(const std::vector<PageDimension>& dimensions, std::size_t v,
                              const Camera& camera, const SheetViewFit& fit, double scale,
                              const PageLayout& layout) {
  ViewMargins out;
  if (fit.extent.empty()) return out;
  // The drawing's box on the page: picture y grows upwards, page y downwards.
  const Rect2 drawing{fit.at_mm.x + scale * fit.extent.xmin, fit.at_mm.y - scale * fit.extent.ymax,
                      fit.at_mm.x + scale * fit.extent.xmax, fit.at_mm.y - scale * fit.extent.ymin};
  for (const PageDimension& d : dimensions) {
    if (d.view != v) continue;
    for (const std::vector<Point2>& stroke : dimension_strokes(d, camera, layout).strokes)
      for (const Point2& p : stroke) {
        out.left = std::max(out.left, drawing.xmin - p.x);
        out.right = std::max(out.right, p.x - drawing.xmax);
        out.top = std::max(out.top, drawing.ymin - p.y);
        out.bottom = std::max(out.bottom, p.y - drawing.ymax);
      }
  }
  return out;
}

// The views of `views of PART`: placed in their grid at one scale — theirs, else the paper's, else the
// largest ISO scale at which the grid fits the sheet above the title block — which they then keep.
void place_grid_views(const FrameScene& scene, const PageSpec& spec, bool framed,
                      std::vector<SheetViewFit>& fits) {
  std::vector<std::size_t> placed;
  std::vector<GridViewFit> grid;
  for (std::size_t i = 0; i < scene.views.size(); ++i)
    if (const std::optional<ViewGridCell>& cell = scene.views[i].grid) {
      placed.push_back(i);
      grid.push_back({cell->column, cell->row, fits[i].extent, fits[i].label_band_mm, fits[i].dimensions});
    }
  if (placed.empty()) return;
  const ViewSetting& first = scene.views[placed.front()];
  const double gap = first.grid->gap_mm;
  const SheetFrame sheet = sheet_frame(spec);
  Rect2 area = sheet.frame;
  area = {area.xmin + kViewGapMm, area.ymin + kViewGapMm, area.xmax - kViewGapMm, area.ymax - kViewGapMm};
  if (framed && !sheet.title_block.empty())
    area.ymax = std::min(area.ymax, sheet.title_block.ymin - kViewGapMm);
  const double scale = first.mm_per_unit  ? *first.mm_per_unit
                       : spec.mm_per_unit ? *spec.mm_per_unit
                                          : fitted_grid_scale(grid, area, gap);
  const std::vector<Point2> points = grid_view_points(grid, scale, area, gap);
  for (std::size_t k = 0; k < placed.size(); ++k) {
    fits[placed[k]].at_mm = points[k];
    fits[placed[k]].mm_per_unit = scale;
  }
}

}  // namespace

SheetDrawing render_sheet(const FrameScene& scene, const PageSpec& spec, bool framed, HiddenStyle hidden,
                          const HlrOptions& hlr, const ViewRenderer& render,
                          const std::vector<PageDimension>& dimensions) {
  SheetDrawing out;
  out.hidden = hidden;
  std::vector<SheetViewFit> fits;
  std::vector<double> per_picture;  // each view's world units per picture unit
  for (const ViewSetting& v : scene.views) {
    HlrOptions options = hlr;
    const bool drawn = v.hidden.value_or(hidden.drawn());
    options.include_hidden = drawn;
    options.max_level = drawn ? hidden.max_level() : 0;
    if (drawn && !out.hidden.drawn()) out.hidden = HiddenStyle::dashed();
    FrameResult result;
    if (v.shows) {
      // Its own solids, numbered after the frame's and those of the views before it.
      const auto first = static_cast<std::uint32_t>(scene.scene.objects.size() + out.shown_names.size());
      result = render(*v.shows, v.camera.camera, options);
      for (VisibleSegment& piece : result.segments) {
        piece.object += first;
        piece.other += first;
      }
      for (std::size_t i = 0; i < v.shows->objects.size(); ++i) {
        out.shown_names.push_back(v.shows->objects[i].name);
        out.shown_pens.push_back(i < v.show_pens.size() ? v.show_pens[i] : 1);
        out.shown_hatch_pens.push_back(v.shows->objects[i].solid->hatch_pen);
      }
    } else {
      result = render(scene.scene, v.camera.camera, options);
    }
    SheetView view;
    view.name = v.camera.name;
    view.camera = v.camera.camera;
    view.label = v.label;
    view.first_segment = out.segments.size();
    out.segments.insert(out.segments.end(), std::make_move_iterator(result.segments.begin()),
                        std::make_move_iterator(result.segments.end()));
    view.end_segment = out.segments.size();
    out.views.push_back(std::move(view));
    const FrameStats& s = result.stats;
    out.stats.candidate_edges += s.candidate_edges;
    out.stats.occluder_faces += s.occluder_faces;
    out.stats.face_tests += s.face_tests;
    out.stats.intersection_lines += s.intersection_lines;
    out.stats.visible_segments += s.visible_segments;
    out.stats.ms.self_crossings += s.ms.self_crossings;
    out.stats.ms.setup += s.ms.setup;
    out.stats.ms.grid += s.ms.grid;
    out.stats.ms.examine += s.ms.examine;
    out.stats.ms.finish += s.ms.finish;

    // World units per picture unit; a perspective camera without a target takes the scene's centre.
    double fallback = 0;
    if (v.camera.camera.projection == Projection::Perspective && v.camera.camera.target_depth <= 0) {
      Box3 bounds;
      for (const SceneObject& o : (v.shows ? *v.shows : scene.scene).objects)
        for (const Point3& p : o.solid->vertices) bounds.include(p);
      if (bounds.lo.x <= bounds.hi.x)
        fallback = v.camera.camera
                       .view(Point3{0.5 * (bounds.lo.x + bounds.hi.x), 0.5 * (bounds.lo.y + bounds.hi.y),
                                    0.5 * (bounds.lo.z + bounds.hi.z)})
                       .z;
    }
    const double k = world_per_picture_unit(v.camera.camera, fallback);
    per_picture.push_back(k);
    SheetViewFit fit;
    fit.at_mm = v.at_mm;
    fit.mm_per_unit = v.mm_per_unit;
    if (v.camera.camera.frame) {
      fit.extent = *v.camera.camera.frame;
    } else {
      fit.extent = Rect2::none();
      for (std::size_t i = out.views.back().first_segment; i < out.segments.size(); ++i) {
        const VisibleSegment& piece = out.segments[i];
        if (piece.hidden && !drawn) continue;
        fit.extent.include(piece.s0);
        fit.extent.include(piece.s1);
      }
    }
    if (!fit.extent.empty())
      fit.extent = {k * fit.extent.xmin, k * fit.extent.ymin, k * fit.extent.xmax, k * fit.extent.ymax};
    fit.label_band_mm = v.label.empty() ? 0 : kViewLabelBandMm;
    fits.push_back(fit);
  }
  // The layout, fitted with the room the dimensions take: that room is measured on a layout, so fit, measure
  // and fit again while it grows (a dimension between points inside the drawing reaches further out as the
  // drawing shrinks); a few rounds settle it on the ISO ladder.
  const Rect2 keep_out = framed ? sheet_frame(spec).title_block : Rect2::none();
  double sheet_scale = 1;
  for (int round = 0; round < 4; ++round) {
    place_grid_views(scene, spec, framed, fits);
    sheet_scale = fitted_sheet_scale(fits, spec, keep_out);
    if (dimensions.empty()) break;
    bool grew = false;
    for (std::size_t i = 0; i < fits.size(); ++i) {
      const double scale = fits[i].mm_per_unit.value_or(sheet_scale);
      const ViewMargins room =
          dimension_margins(dimensions, i, out.views[i].camera, fits[i], scale,
                            view_layout(spec.paper, fits[i].at_mm, scale * per_picture[i]));
      ViewMargins& kept = fits[i].dimensions;
      constexpr double settled = Tolerance::kSheetMarginSlackMm;
      grew |= room.left > kept.left + settled || room.top > kept.top + settled ||
              room.right > kept.right + settled || room.bottom > kept.bottom + settled;
      kept = {std::max(kept.left, room.left), std::max(kept.top, room.top), std::max(kept.right, room.right),
              std::max(kept.bottom, room.bottom)};
    }
    if (!grew) break;
  }
  // The title block's scale: the sheet's when a view is drawn at it, else the views' own when they share
  // one, else "AS SHOWN"; a view at another scale says so under it, as drawings do: "DETAIL (2:1)".
  std::optional<double> title_scale;
  if (std::any_of(fits.begin(), fits.end(), [](const SheetViewFit& f) { return !f.mm_per_unit; }))
    title_scale = sheet_scale;
  else if (std::all_of(fits.begin(), fits.end(),
                       [&](const SheetViewFit& f) { return f.mm_per_unit == fits.front().mm_per_unit; }))
    title_scale = fits.front().mm_per_unit;
  out.scale_text = title_scale ? scale_ratio_text(*title_scale) : "AS SHOWN";
  for (std::size_t i = 0; i < out.views.size(); ++i) {
    const double scale = fits[i].mm_per_unit.value_or(sheet_scale);
    out.views[i].layout = view_layout(spec.paper, fits[i].at_mm, scale * per_picture[i]);
    out.views[i].mm_per_world_unit = scale;
    if (!out.views[i].label.empty() && scale != title_scale)
      out.views[i].label += " (" + scale_ratio_text(scale) + ")";
  }
  return out;
}

std::vector<PageDimension> sheet_dimensions(const FrameScene& scene) {
  std::vector<PageDimension> out;
  std::string names;
  for (const ViewSetting& v : scene.views) names += (names.empty() ? "" : ", ") + v.camera.name;
  for (const DimensionSetting& setting : scene.dimensions) {
    PageDimension d = setting.dimension;
    if (!setting.view_name) {
      if (scene.views.size() != 1)
        fail(setting.span,
             "say which view the dimension is drawn in: the sheet has " + std::to_string(scene.views.size()) +
                 " views",
             "add 'in NAME' after the points; the views: " + names);
      d.view = 0;
    } else {
      const auto it = std::find_if(scene.views.begin(), scene.views.end(),
                                   [&](const ViewSetting& v) { return v.camera.name == *setting.view_name; });
      if (it == scene.views.end())
        fail(setting.view_span, "the sheet has no view named '" + *setting.view_name + "'",
             "the views: " + names);
      d.view = static_cast<std::size_t>(it - scene.views.begin());
    }
    out.push_back(std::move(d));
  }
  return out;
}

std::vector<lang::Diagnostic> sheet_warnings(const FrameScene& scene, const PageSpec& spec,
                                             const std::vector<Rect2>& boxes, bool framed) {
  std::vector<lang::Diagnostic> out;
  const auto warn = [&](const ViewSetting& v, std::string message, std::string hint) {
    lang::Diagnostic d;
    d.severity = lang::Severity::Warning;
    d.span = v.camera.span;
    d.message = "view '" + v.camera.name + "': " + std::move(message);
    d.hint = std::move(hint);
    out.push_back(std::move(d));
  };
  const double m = spec.margin_mm, w = spec.paper.width_mm, h = spec.paper.height_mm;
  const Rect2 inside{m, m, w - m, h - m};
  const Rect2 title = framed ? sheet_frame(spec).title_block : Rect2::none();
  for (std::size_t i = 0; i < scene.views.size() && i < boxes.size(); ++i) {
    const ViewSetting& v = scene.views[i];
    if (!v.grid && !inside.contains(v.at_mm)) {  // a grid's views are placed inside
      warn(v, "its point lies outside the page's margins",
           "put it within the margins, as in 'at page (" + std::to_string(int(w / 2)) + ", " +
               std::to_string(int(h / 2)) + ")'");
      continue;
    }
    const Rect2& box = boxes[i];
    if (box.empty()) continue;
    const double slack = Tolerance::kSheetMarginSlackMm;
    if (box.xmin < inside.xmin - slack || box.ymin < inside.ymin - slack || box.xmax > inside.xmax + slack ||
        box.ymax > inside.ymax + slack) {
      warn(v, "its drawing runs past the page's margins", "give it a smaller scale:, or move it");
      continue;
    }
    bool overlapping = false;
    for (std::size_t j = 0; j < i && !overlapping; ++j)
      if (!boxes[j].empty() && box.overlaps(boxes[j])) {
        warn(v, "its drawing overlaps view '" + scene.views[j].camera.name + "'",
             "move one of them, or give them a smaller scale:");
        overlapping = true;
      }
    if (!overlapping && !title.empty() && box.overlaps(title))
      warn(v, "its drawing overlaps the title block in the bottom-right corner",
           "move it, or give it a smaller scale:");
  }
  return out;
}

}  // namespace hlr::runtime
