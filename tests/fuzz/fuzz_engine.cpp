// Fuzz target: the hidden-line engine and the pen plan on small solids and a camera decoded from the
// bytes. Solids the builder rejects and cameras the constructors reject are expected (the input is then
// skipped); a crash, a sanitizer report, an exception escaping or a piece that cannot be right (not
// finite, not where the camera projects its end points, outside the frame) is a finding.
//
// Layout (bytes past the end read as 0; coordinates are signed bytes × 0.5, so small grids with exact
// coincidences):
//   flags   bit 0 orthographic, 1 hidden pieces too, 2 no intersection lines, 3 coincident pieces kept,
//           bits 4-5 frame aspect (none, 1, 1.5, 0.25), bits 6-7 pen order (none, greedy, optimized ×2)
//   eye xyz, target xyz, up (0 z, 1 y, 2 x, 3 the diagonal), lens (fov 1 + b·0.7° or height 0.5 + b/4)
//   solid count (1 + b % 3), then per solid:
//     vertex count (3 + b % 14), options (bit 0 mirrored, bits 1-7 crease angle in degrees), turn (0 none,
//     else about axis b % 4 as for up, by (b >> 2) · 360°/64: off-grid coordinates), vertices xyz,
//     record count (b % 24), records: r = kind (r >> 6: 0-1 a face, 2 a face with one hole, 3 a line)
//     and size (3 + r % 8 vertices), then the vertex numbers (b % vertex count); a hole's record is a size
//     byte (3 + b % 8) and its vertex numbers; a line's is its two vertex numbers.
// tests/fuzz/write_seeds.py writes the seeds in this layout.
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/camera/camera_error.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/device/page/page_plot.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"
#include "tests/fuzz/fuzz_input.hpp"

namespace {

using hlr::fuzz::ByteReader;

double coordinate(ByteReader& in) { return 0.5 * in.signed_byte(); }
hlr::Point3 point(ByteReader& in) {
  const double x = coordinate(in), y = coordinate(in);
  return {x, y, coordinate(in)};
}

constexpr hlr::Vector3 kAxes[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}};

std::vector<hlr::VertexIndex> ring(ByteReader& in, std::size_t size, std::size_t vertices) {
  std::vector<hlr::VertexIndex> r(size);
  for (hlr::VertexIndex& v : r) v = static_cast<hlr::VertexIndex>(in.byte() % vertices);
  return r;
}

// One solid, or nothing when the builder rejects it.
std::optional<hlr::Solid> decode_solid(ByteReader& in) {
  const std::size_t vertices = 3 + in.byte() % 14;
  const std::uint8_t options = in.byte();
  const std::uint8_t turn = in.byte();
  hlr::SolidBuildOptions build;
  build.crease_angle_deg = options >> 1;
  hlr::SolidBuilder builder(build);
  for (std::size_t v = 0; v < vertices; ++v) builder.add_vertex(point(in));
  for (std::size_t records = in.byte() % 24; records > 0; --records) {
    const std::uint8_t r = in.byte();
    const int kind = r >> 6;
    if (kind == 3) {
      const auto a = static_cast<hlr::VertexIndex>(in.byte() % vertices);
      builder.add_indexed_line(a, static_cast<hlr::VertexIndex>(in.byte() % vertices));
      continue;
    }
    std::vector<std::vector<hlr::VertexIndex>> rings;
    rings.push_back(ring(in, 3 + r % 8, vertices));
    if (kind == 2) rings.push_back(ring(in, 3 + in.byte() % 8, vertices));
    builder.add_indexed_face(rings);
  }
  hlr::SolidBuildResult built = builder.build();
  if (!built.ok()) return std::nullopt;
  hlr::Affine3 placement = hlr::Affine3::identity();
  if (options & 1) placement = hlr::Affine3::scaling(-1, 1, 1);
  if (turn != 0)
    placement = placement.then(hlr::Affine3::rotation(kAxes[turn % 4], (turn >> 2) * std::numbers::pi / 32));
  if ((options & 1) || turn != 0) return built.solid->transformed(placement);
  return std::move(built.solid);
}

std::optional<hlr::Camera> decode_camera(ByteReader& in, std::uint8_t flags) {
  const hlr::Point3 eye = point(in), target = point(in);
  const hlr::Vector3 up = kAxes[in.byte() % 4];
  const std::uint8_t lens = in.byte();
  static constexpr double kAspects[] = {0, 1, 1.5, 0.25};
  const double aspect = kAspects[(flags >> 4) & 3];
  try {
    if (flags & 1) return hlr::ortho_camera({eye, target, up, 0.5 + lens / 4.0, aspect});
    return hlr::lookat_camera({eye, target, up, 1 + lens * 0.7, aspect, 0});
  } catch (const hlr::CameraError&) {
    return std::nullopt;
  }
}

// What every piece must be: finite, of an edge that exists, its picture points the camera's projection
// of its world points, in front of the near plane and inside the frame (up to rounding).
bool plausible(const hlr::VisibleSegment& s, const hlr::Scene& scene, const hlr::Camera& camera,
               const hlr::HlrOptions& options) {
  if (!hlr::is_finite(s.p0) || !hlr::is_finite(s.p1) || !std::isfinite(s.s0.x + s.s0.y + s.s1.x + s.s1.y))
    return false;
  if (s.hidden && !options.include_hidden) return false;
  if (s.object >= scene.objects.size()) return false;
  if (s.source == hlr::SegmentSource::Edge && s.edge >= scene.objects[s.object].solid->edges.size())
    return false;
  if (s.source == hlr::SegmentSource::Intersection && s.other >= scene.objects.size()) return false;
  for (const auto& [world, picture] : {std::pair{s.p0, s.s0}, std::pair{s.p1, s.s1}}) {
    const hlr::Point3 view = camera.view(world);
    if (camera.projection == hlr::Projection::Perspective && view.z < camera.near_depth * (1 - 1e-9))
      return false;
    const hlr::Point2 projected = camera.project_view(view);
    const double scale = 1 + std::abs(picture.x) + std::abs(picture.y);
    if (std::abs(projected.x - picture.x) + std::abs(projected.y - picture.y) > 1e-6 * scale) return false;
    if (camera.frame) {
      const double slack = 1e-9 * (1 + camera.frame->width() + camera.frame->height());
      if (picture.x < camera.frame->xmin - slack || picture.x > camera.frame->xmax + slack ||
          picture.y < camera.frame->ymin - slack || picture.y > camera.frame->ymax + slack)
        return false;
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const std::uint8_t flags = in.byte();
  const std::optional<hlr::Camera> camera = decode_camera(in, flags);
  if (!camera) return 0;
  hlr::Scene scene;
  for (int solids = 1 + in.byte() % 3; solids > 0; --solids)
    if (std::optional<hlr::Solid> solid = decode_solid(in))
      scene.objects.emplace_back("solid" + std::to_string(scene.objects.size()), std::move(*solid));
  if (scene.objects.empty()) return 0;

  hlr::HlrOptions options;
  options.include_hidden = flags & 2;
  options.intersection_lines = !(flags & 4);
  options.coincident_once = !(flags & 8);
  options.threads = 1;
  const hlr::FrameResult result = hlr::render_frame(scene, *camera, options);
  for (const hlr::VisibleSegment& s : result.segments)
    if (!plausible(s, scene, *camera, options)) std::abort();

  hlr::PagePlotOptions plot;
  plot.hidden = options.include_hidden ? hlr::HiddenStyle::dashed() : hlr::HiddenStyle::off();
  static constexpr hlr::PenOrder kOrders[] = {hlr::PenOrder::None, hlr::PenOrder::Greedy,
                                              hlr::PenOrder::Optimized, hlr::PenOrder::Optimized};
  plot.plan.order = kOrders[flags >> 6];
  plot.plan.effort = 20;  // the improvement passes stop early: each input stays quick
  (void)hlr::plot_page(result.segments, camera->frame, "", plot);
  return 0;
}
