#include "runtime/pipeline/frame_labels.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/device/page/stroke_text.hpp"
#include "core/solid/solid_builder.hpp"

namespace hlr::runtime {

bool has_world_labels(const std::vector<LabelSetting>& labels) {
  return std::any_of(labels.begin(), labels.end(), [](const LabelSetting& l) { return !l.on_page; });
}

void add_world_labels(const std::vector<LabelSetting>& labels, const Camera& camera, const PageLayout& layout,
                      Scene& scene, std::vector<int>& pens) {
  const Affine3 worldFromView = camera.viewFromWorld.inverse();
  const bool perspective = camera.projection == Projection::Perspective;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const LabelSetting& label = labels[i];
    if (label.on_page || label.text.empty()) continue;
    const Point3 anchor = camera.view(label.at);
    if (perspective && !(anchor.z > camera.near_depth)) continue;  // behind the eye: nothing to draw
    const Point2 start = layout.to_page_mm(camera.project_view(anchor));
    // Page mm → picture → view space at the anchor's depth → world.
    const auto to_world = [&](Point2 page) {
      const Point2 picture{layout.picture_centre.x + (page.x - 0.5 * layout.page_width_mm) / layout.scale,
                           layout.picture_centre.y - (page.y - 0.5 * layout.page_height_mm) / layout.scale};
      const double per = perspective ? anchor.z / camera.focal : 1 / camera.focal;
      return worldFromView.apply(
          Point3{(picture.x - camera.offset.x) * per, (picture.y - camera.offset.y) * per, anchor.z});
    };
    // Letters meet and strokes close on themselves: one vertex per page point (the builder refuses two
    // vertices at one place).
    SolidBuilder builder;
    std::map<std::pair<double, double>, VertexIndex> vertex_at;
    const auto vertex = [&](Point2 page) {
      const auto [it, added] = vertex_at.try_emplace({page.x, page.y}, VertexIndex{});
      if (added) it->second = builder.add_vertex(to_world(page));
      return it->second;
    };
    for (const std::vector<Point2>& stroke : stroke_text(label.text, start, label.size_mm))
      for (std::size_t k = 1; k < stroke.size(); ++k) {
        const VertexIndex a = vertex(stroke[k - 1]), b = vertex(stroke[k]);
        if (a != b) builder.add_indexed_line(a, b);
      }
    SolidBuildResult built = builder.build();
    if (!built.ok()) continue;  // letters too small for the builder's tolerance: nothing to draw
    scene.objects.emplace_back("label " + std::to_string(i + 1), std::move(*built.solid));
    pens.push_back(label.pen);
  }
}

Rect2 with_label_boxes(Rect2 extent, const std::vector<LabelSetting>& labels, const Camera& camera,
                       const PageSpec& spec) {
  const bool perspective = camera.projection == Projection::Perspective;
  struct Box {
    Point2 anchor;                       // picture
    double width = 0, up = 0, down = 0;  // page mm from the baseline's start
  };
  std::vector<Box> boxes;  // world labels in front of the eye
  for (const LabelSetting& label : labels) {
    if (label.on_page || label.text.empty()) continue;
    const Point3 view = camera.view(label.at);
    if (perspective && !(view.z > camera.near_depth)) continue;
    boxes.push_back({camera.project_view(view), stroke_text_width_mm(label.text, label.size_mm),
                     label.size_mm, label.size_mm * kStrokeTextDescent});
    extent.include(boxes.back().anchor);
  }
  if (boxes.empty()) return extent;
  // The extent at `scale` mm per picture unit: the texts' boxes shrink in picture units as it grows.
  const auto extent_at = [&](double scale) {
    Rect2 e = extent;
    for (const Box& b : boxes) {
      e.include({b.anchor.x + b.width / scale, b.anchor.y + b.up / scale});  // picture y runs up
      e.include({b.anchor.x, b.anchor.y - b.down / scale});
    }
    return e;
  };
  if (spec.mm_per_unit) return extent_at(*spec.mm_per_unit);
  // The largest scale whose extent still fits at that scale: the fit of extent_at(s) grows with s, slower
  // than s once the texts matter, so bisect between a scale that fits and the solids' own fit.
  const auto fits = [&](double scale) { return fit_rect_to_page(extent_at(scale), spec).scale >= scale; };
  double hi = fit_rect_to_page(extent, spec).scale;
  if (fits(hi)) return extent_at(hi);
  double lo = hi;
  for (int i = 0; i < 64 && !fits(lo); ++i) lo /= 2;
  if (!fits(lo)) return extent_at(hi);  // a text wider than the page: it runs off, the drawing stays
  for (int i = 0; i < 64; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? lo : hi) = mid;
  }
  return extent_at(lo);
}

std::vector<PageText> page_labels(const std::vector<LabelSetting>& labels) {
  std::vector<PageText> out;
  for (const LabelSetting& label : labels)
    if (label.on_page) out.push_back({label.text, {label.at.x, label.at.y}, label.size_mm, label.pen});
  return out;
}

}  // namespace hlr::runtime
