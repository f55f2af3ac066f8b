#include "runtime/frame_labels.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/device/stroke_text.hpp"
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

std::vector<PageText> page_labels(const std::vector<LabelSetting>& labels) {
  std::vector<PageText> out;
  for (const LabelSetting& label : labels)
    if (label.on_page) out.push_back({label.text, {label.at.x, label.at.y}, label.size_mm, label.pen});
  return out;
}

}  // namespace hlr::runtime
