#include "core/hlr/intersection_lines.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/box3.hpp"
#include "core/solid/face_crossing.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

Box3 face_box(const Solid& solid, const Face& face) {
  Box3 b;
  for (VertexIndex v : face.rings[0].vertices) b.include(solid.vertices[v]);
  return b;
}

}  // namespace

void add_intersection_candidates(const Scene& scene, const Camera& camera,
                                 const std::vector<std::vector<std::int8_t>>& facing,
                                 const std::vector<char>& cull, double tol, bool keep_culled,
                                 FrameSetup& setup) {
  const std::size_t n = scene.objects.size();
  std::vector<Box3> boxes(n);
  for (std::size_t o = 0; o < n; ++o)
    for (Point3 p : scene.objects[o].solid->vertices) boxes[o].include(p);

  struct FaceRef {
    FaceIndex face;
    Box3 box;
  };
  // A face of a closed solid that faces away lies behind the solid's own front faces: the intersection
  // lines on it are hidden.
  auto culled_face = [&](std::size_t o, FaceIndex f) { return cull[o] && facing[o][f] <= 0; };
  auto faces_of = [&](std::size_t o, const Box3& clip) {
    std::vector<FaceRef> refs;
    const Solid& s = *scene.objects[o].solid;
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      const Box3 b = face_box(s, s.faces[f]);
      if (b.overlaps(clip, tol)) refs.push_back({static_cast<FaceIndex>(f), b});
    }
    std::sort(refs.begin(), refs.end(),
              [](const FaceRef& a, const FaceRef& b) { return a.box.lo.x < b.box.lo.x; });
    return refs;
  };

  FaceCrossingScratch scratch;
  std::vector<CrossingPiece> pieces;
  std::uint32_t piece_index = 0;
  auto add = [&](std::size_t i, FaceIndex fa, std::size_t j, FaceIndex fb, const CrossingPiece& piece) {
    // Pieces are numbered whether or not they are kept, so a piece has the same number with and without
    // the hidden layer.
    const bool culled = culled_face(i, fa) || culled_face(j, fb);
    if (culled && !keep_culled) {
      ++piece_index;
      return;
    }
    Candidate c;
    c.source = SegmentSource::Intersection;
    c.object = static_cast<std::uint32_t>(i);
    c.other = static_cast<std::uint32_t>(j);
    c.edge = piece_index++;
    c.own_face0 = fa;
    c.own_face1 = fb;
    c.view0 = camera.view(piece.p0);
    c.view1 = camera.view(piece.p1);
    c.culled = culled;
    setup.candidates.push_back(c);
  };
  // Broad phase: sweep the objects' boxes along x, so cities of many separate solids stay near-linear.
  std::vector<std::size_t> order(n);
  for (std::size_t o = 0; o < n; ++o) order[o] = o;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return boxes[a].lo.x < boxes[b].lo.x; });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n && boxes[order[b]].lo.x <= boxes[order[a]].hi.x + tol; ++b)
      if (boxes[order[a]].overlaps(boxes[order[b]], tol))
        pairs.emplace_back(std::min(order[a], order[b]), std::max(order[a], order[b]));
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [i, j] : pairs) {
    {
      const Solid& si = *scene.objects[i].solid;
      const Solid& sj = *scene.objects[j].solid;
      const std::vector<FaceRef> fa = faces_of(i, boxes[j]), fb = faces_of(j, boxes[i]);
      // Sweep over x: each face of i meets the faces of j whose x-range overlaps.
      std::size_t start = 0;
      for (const FaceRef& a : fa) {
        while (start < fb.size() && fb[start].box.hi.x < a.box.lo.x - tol) ++start;
        for (std::size_t k = start; k < fb.size() && fb[k].box.lo.x <= a.box.hi.x + tol; ++k) {
          const FaceRef& b = fb[k];
          if (b.box.hi.x < a.box.lo.x - tol || !a.box.overlaps(b.box, tol)) continue;
          if (!face_meets_plane(sj, b.face, si.planes[a.face], tol)) continue;
          pieces.clear();
          face_crossings(si, a.face, sj, b.face, tol, scratch, pieces);
          for (const CrossingPiece& piece : pieces) add(i, a.face, j, b.face, piece);
        }
      }
    }
  }
  // Where a solid passes through itself: found once per solid (it is rigid) and kept with it.
  for (std::size_t o = 0; o < n; ++o)
    for (const SelfCrossing& x : scene.objects[o].solid->self_crossings())
      add(o, x.face0, o, x.face1, {x.p0, x.p1});
}

}  // namespace hlr
