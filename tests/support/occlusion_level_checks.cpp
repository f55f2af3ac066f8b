#include "tests/support/occlusion_level_checks.hpp"

#include <sstream>
#include <unordered_map>

#include "tests/support/ray_caster_checks.hpp"

namespace hlr::test {
namespace {

void fail(LevelReport& r, const std::string& message) {
  if (r.failures.size() < 8) r.failures.push_back(message);
}

}  // namespace

std::string LevelReport::summary() const {
  std::ostringstream s;
  s << "piece samples " << piece_samples << " (wrong level " << piece_wrong << "), edge samples "
    << edge_samples << " (hidden " << edge_hidden << ", missing " << edge_missing
    << ", drawn past the last level " << edge_beyond_drawn << "), ambiguous " << ambiguous
    << "; hidden samples by level:";
  for (std::size_t k = 1; k < samples_per_level.size(); ++k) s << " " << k << ":" << samples_per_level[k];
  for (const std::string& f : failures) s << "\n  " << f;
  return s.str();
}

LevelReport check_occlusion_levels(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                   unsigned max_level, int edge_samples) {
  LevelReport r;
  r.samples_per_level.assign(max_level + 1, 0);
  const Camera& cam = oracle.camera();
  const double eps = 1e-6 * picture_extent(scene, cam, result);

  // (a) each piece's samples have its level.
  for (const VisibleSegment& s : result.segments) {
    for (const Point3& p : segment_samples(s)) {
      ++r.piece_samples;
      const std::optional<int> count = oracle.surfaces_in_front(p);
      if (!count) {
        ++r.ambiguous;
        continue;
      }
      if (*count != s.level) {
        ++r.piece_wrong;
        std::ostringstream m;
        m << (s.source == SegmentSource::Edge ? "edge " : "intersection piece ") << s.edge << " of object "
          << s.object << ", level " << s.level << ": point " << str(p) << " has " << *count
          << " surfaces in front";
        fail(r, m.str());
        break;  // one message per piece
      }
    }
  }

  // (b) each drawn-candidate edge's hidden samples lie on a piece of their level.
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> pieces;
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const VisibleSegment& s = result.segments[i];
    if (s.source == SegmentSource::Edge) pieces[(std::uint64_t{s.object} << 32) | s.edge].push_back(i);
  }
  for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Solid& solid = *scene.objects[o].solid;
    for (std::uint32_t e = 0; e < solid.edges.size(); ++e) {
      const SolidEdge& edge = solid.edges[e];
      if (drawn_candidate(oracle, o, solid, edge) != Candidate::Yes) continue;
      const Point3 v0 = solid.vertices[edge.v0], v1 = solid.vertices[edge.v1];
      // Seen end-on an edge is a point of the picture: nothing need be drawn.
      if (in_front(cam, v0) && in_front(cam, v1) && distance(cam.project(v0), cam.project(v1)) < 10 * eps)
        continue;
      const auto it = pieces.find((std::uint64_t{o} << 32) | e);
      for (int i = 0; i < edge_samples; ++i) {
        const Point3 p = lerp(v0, v1, (i + 0.5) / edge_samples);
        ++r.edge_samples;
        const std::optional<int> count = oracle.surfaces_in_front(p);
        if (!count) {
          ++r.ambiguous;
          continue;
        }
        if (*count == 0 || !in_front(cam, p)) continue;  // visible: check_frame's part
        const Point2 pic = cam.project(p);
        if (!in_frame(cam, pic, -eps)) continue;
        ++r.edge_hidden;
        bool on_level = false, on_any = false;
        if (it != pieces.end())
          for (std::size_t si : it->second) {
            const VisibleSegment& s = result.segments[si];
            if (point_segment_distance(pic, s.s0, s.s1) >= eps) continue;
            on_any = true;
            on_level = on_level || s.level == *count;
          }
        if (*count <= static_cast<int>(max_level)) {
          ++r.samples_per_level[static_cast<std::size_t>(*count)];
          if (on_level) continue;
          ++r.edge_missing;
          std::ostringstream m;
          m << "missing: object " << o << " edge " << e << " point " << str(p) << " behind " << *count
            << " surfaces is on no piece of that level";
          fail(r, m.str());
          break;
        }
        if (on_any) {
          ++r.edge_beyond_drawn;
          std::ostringstream m;
          m << "drawn: object " << o << " edge " << e << " point " << str(p) << " behind " << *count
            << " surfaces, past level " << max_level;
          fail(r, m.str());
          break;
        }
      }
    }
  }
  return r;
}

}  // namespace hlr::test
