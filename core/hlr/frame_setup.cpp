#include "core/hlr/frame_setup.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "core/first_touch.hpp"
#include "core/geometry/box3.hpp"
#include "core/geometry/exact_predicates.hpp"
#include "core/hlr/intersection_lines.hpp"
#include "core/hlr/smooth_contours.hpp"
#include "core/parallel.hpp"
#include "core/release_memory.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

bool is_perspective(const Camera& camera) { return camera.projection == Projection::Perspective; }

// Objects with at least this many faces are prepared in slices of this many faces (and edges), in
// parallel; smaller ones whole, in runs.
constexpr std::size_t kSliceFaces = 8192;

// The view-space tolerance of the frame: relative to the view-space coordinates, plus the rounding their
// world-space sources carry (far from the origin, a view coordinate inherits the world coordinate's).
Tolerance frame_tolerance(const Scene& scene, const Camera& camera) {
  double view = 0, world = 0;
  for (const SceneObject& object : scene.objects)
    for (Point3 p : object.solid->vertices) {
      const Point3 v = camera.view(p);
      view = std::max({view, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
      world = std::max({world, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
  if (camera.projection == Projection::Perspective) {
    const Point3 eye = camera.eye_world();
    world = std::max({world, std::abs(eye.x), std::abs(eye.y), std::abs(eye.z)});
  }
  return Tolerance::for_view(view, world);
}

// Sutherland–Hodgman against depth ≥ near, carrying each edge's seam flag. For a non-convex ring the
// result may contain edges doubled along the clip line; containment is even-odd, so they cancel. Edges
// along the clip line are outline, not seam.
void clip_ring_to_near(const std::vector<Point3>& ring, const std::vector<FaceIndex>& seam, double near,
                       std::vector<Point3>& out, std::vector<FaceIndex>& out_seam) {
  out.clear();
  out_seam.clear();
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point3& a = ring[i];
    const Point3& b = ring[(i + 1) % n];
    const bool a_in = a.z >= near, b_in = b.z >= near;
    if (a_in) {
      out.push_back(a);
      out_seam.push_back(seam[i]);
    }
    if (a_in != b_in) {
      out.push_back(lerp(a, b, (near - a.z) / (b.z - a.z)));
      out_seam.push_back(a_in ? kNoFace : seam[i]);  // leaving: along the clip line; entering: rest of a→b
    }
  }
}

// True when every vertex lies in front of the near plane: a closed solid there encloses no part of
// the eye's neighbourhood, so its back faces are hidden by its front faces.
bool wholly_in_front(std::span<const Point3> view_vertices, const Camera& camera, double tolerance) {
  if (!is_perspective(camera)) return true;
  return std::all_of(view_vertices.begin(), view_vertices.end(),
                     [&](const Point3& v) { return v.z >= camera.near_depth + tolerance; });
}

// Per object: whether its bounding box meets another object's (grown by `tol`), by a sweep along x.
std::vector<char> boxes_meeting_others(const Scene& scene, double tol) {
  const std::size_t n = scene.objects.size();
  std::vector<Box3> boxes(n);
  for (std::size_t o = 0; o < n; ++o)
    for (const Point3& p : scene.objects[o].solid->vertices) boxes[o].include(p);
  std::vector<std::size_t> order(n);
  for (std::size_t o = 0; o < n; ++o) order[o] = o;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].lo.x < boxes[b].lo.x; });
  std::vector<char> meets(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n && boxes[order[j]].lo.x <= boxes[order[i]].hi.x + tol; ++j)
      if (boxes[order[i]].overlaps(boxes[order[j]], tol)) meets[order[i]] = meets[order[j]] = 1;
  return meets;
}

// Where one job of prepare_frame writes in the frame's lists: from these first slots on, no more than its
// counting pass made room for. Point and ring numbers are the frame's.
struct Slots {
  Occluder* occluders = nullptr;
  Point2* points = nullptr;
  FaceIndex* seams = nullptr;
  std::uint32_t* ring_ends = nullptr;
  Candidate* candidates = nullptr;
  std::uint32_t point_base = 0, ring_base = 0;  // the frame's numbers of points[0] and ring_ends[0]
  std::size_t occluder_count = 0, point_count = 0, ring_count = 0, candidate_count = 0;
};

// How much of each list a job fills at most.
struct Room {
  std::size_t occluders = 0, points = 0, rings = 0, candidates = 0;
};

bool occludes(const std::vector<std::int8_t>& facing, bool cull, FaceIndex f) {
  return f != kNoFace && facing[f] != 0 && !(cull && facing[f] < 0);
}

// Room for the occluders of faces [face_begin, face_end). Clipping a ring at the near plane (`clips`) keeps
// its points in front and adds one where it crosses: at most twice as many.
void count_occluders(Room& room, const Solid& solid, const std::vector<std::int8_t>& facing, bool cull,
                     bool clips, std::size_t face_begin, std::size_t face_end) {
  for (std::size_t f = face_begin; f < face_end; ++f) {
    if (!occludes(facing, cull, static_cast<FaceIndex>(f))) continue;
    ++room.occluders;
    for (const Ring& ring : solid.faces[f].rings) room.points += ring.vertices.size() * (clips ? 2 : 1);
    room.rings += solid.faces[f].rings.size();
  }
}

// The occluders of faces [face_begin, face_end).
void add_occluders(Slots& out, std::uint32_t object_index, const Solid& solid, const Point3* view_vertices,
                   const std::vector<std::int8_t>& facing, bool cull, const Camera& camera,
                   std::size_t face_begin, std::size_t face_end) {
  std::vector<Point3> ring_points, clipped;
  std::vector<FaceIndex> ring_seams, clipped_seams;
  for (std::size_t f = face_begin; f < face_end; ++f) {
    if (!occludes(facing, cull, static_cast<FaceIndex>(f))) continue;
    const Face& face = solid.faces[f];
    Occluder occ;
    occ.object = object_index;
    occ.face = static_cast<FaceIndex>(f);
    // The view-space plane, from Newell's normal of the outer ring (exact for planar rings).
    Vector3 normal{};
    Vector3 centroid{};
    const auto& outer = face.rings[0].vertices;
    for (std::size_t i = 0; i < outer.size(); ++i) {
      const Point3 a = view_vertices[outer[i]], b = view_vertices[outer[(i + 1) % outer.size()]];
      normal += Vector3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
      centroid += to_vector(a);
    }
    normal = normalize(normal);
    centroid = centroid / static_cast<double>(outer.size());
    occ.normal = normal;
    occ.offset = -dot(normal, centroid);
    if (is_perspective(camera)) {
      occ.eye_side = occ.offset > 0 ? 1.0 : -1.0;
    } else {
      occ.eye_side = normal.z < 0 ? 1.0 : -1.0;
    }
    const std::size_t first_point = out.point_count, first_ring = out.ring_count;
    occ.first_point = out.point_base + static_cast<std::uint32_t>(first_point);
    occ.first_ring = out.ring_base + static_cast<std::uint32_t>(first_ring);
    occ.bounds = Rect2::none();
    occ.min_depth = 1e300;
    for (const Ring& ring : face.rings) {
      ring_points.clear();
      ring_seams.clear();
      for (std::size_t i = 0; i < ring.vertices.size(); ++i) {
        ring_points.push_back(view_vertices[ring.vertices[i]]);
        // A seam: the neighbour across this edge also hides and faces the same way, so the two project
        // to opposite sides of the edge and together cover it.
        FaceIndex seam = kNoFace;
        if (i < ring.edges.size() && ring.edges[i] != kNoEdge) {
          const SolidEdge& e = solid.edges[ring.edges[i]];
          const FaceIndex other = e.left == static_cast<FaceIndex>(f) ? e.right : e.left;
          if (other != static_cast<FaceIndex>(f) && occludes(facing, cull, other) &&
              facing[other] == facing[f])
            seam = other;
        }
        ring_seams.push_back(seam);
      }
      const std::vector<Point3>* pts = &ring_points;
      const std::vector<FaceIndex>* seams = &ring_seams;
      if (is_perspective(camera)) {
        clip_ring_to_near(ring_points, ring_seams, camera.near_depth, clipped, clipped_seams);
        pts = &clipped;
        seams = &clipped_seams;
      }
      if (pts->size() < 3) continue;
      std::copy(seams->begin(), seams->end(), out.seams + out.point_count);
      for (const Point3& p : *pts) {
        const Point2 q = camera.project_view(p);
        out.points[out.point_count++] = q;
        occ.bounds.include(q);
        occ.min_depth = std::min(occ.min_depth, p.z);
      }
      out.ring_ends[out.ring_count++] = out.point_base + static_cast<std::uint32_t>(out.point_count);
      ++occ.ring_count;
    }
    if (occ.ring_count == 0 || !std::isfinite(occ.bounds.width() + occ.bounds.height() + occ.offset)) {
      // Nothing in front of the near plane, or coordinates beyond double range: it hides nothing.
      out.point_count = first_point;
      out.ring_count = first_ring;
      continue;
    }
    out.occluders[out.occluder_count++] = occ;
  }
}

}  // namespace

void set_picture_tolerance(Candidate& c, const Camera& camera, double length_tolerance) {
  const double max_abs =
      std::max({std::abs(c.pic0.x), std::abs(c.pic0.y), std::abs(c.pic1.x), std::abs(c.pic1.y)});
  const double depth = is_perspective(camera) ? std::min(c.view0.z, c.view1.z) : 1.0;
  c.picture_tolerance = Tolerance::picture(max_abs, camera.focal, length_tolerance, depth);
}

namespace {

struct ViewSide {
  bool perspective = true;
  Point3 eye{};         // world eye (perspective)
  Vector3 direction{};  // world viewing direction
};

// Per face of [begin, end): +1 front, −1 back, 0 edge-on, into `facing` (sized for every face).
bool is_triangle(const Face& face) { return face.rings.size() == 1 && face.rings[0].vertices.size() == 3; }

// A triangle seen within the tolerance of edge-on faces the eye or not exactly (its plane is exact): the
// side of the eye, or of the view direction, by an orientation of its corners. 0 only when exactly edge-on.
int exact_facing(const Solid& solid, std::size_t f, const ViewSide& view) {
  const auto& ring = solid.faces[f].rings[0].vertices;
  const Point3 a = solid.vertices[ring[0]], b = solid.vertices[ring[1]], c = solid.vertices[ring[2]];
  // ((b − a) × (c − a)) points out of the face (counter-clockwise seen from outside).
  if (view.perspective) return orient3d(a, b, c, view.eye);
  return orient3d_along_direction(a, b, view.direction, c, c, 0);  // ((b − a) × d)·(c − a) = −n·d
}

void face_facing(const Solid& solid, const ViewSide& view, double length_tolerance,
                 std::vector<std::int8_t>& facing, std::size_t begin, std::size_t end) {
  for (std::size_t f = begin; f < end; ++f) {
    const Vector3 n = solid.planes[f].normal;
    double s, tol;
    if (view.perspective) {
      // Measured from a vertex of the face, not through the plane's offset: no cancellation far from
      // the origin.
      s = dot(n, view.eye - solid.vertices[solid.faces[f].rings[0].vertices[0]]);
      tol = length_tolerance;
    } else {
      s = -dot(n, view.direction);
      tol = Tolerance::kRelative;
    }
    facing[f] =
        s > tol ? 1 : (s < -tol ? -1 : (is_triangle(solid.faces[f]) ? exact_facing(solid, f, view) : 0));
  }
}

// Whether an edge of one object is a candidate: 0 no, 1 to be examined, 2 hidden by the back-face rules
// alone (kept only when `keep_culled`; a hatch line never is, as it is never drawn hidden).
int edge_use(const Solid& solid, const SolidEdge& edge, const std::vector<std::int8_t>& facing, bool cull,
             bool keep_culled) {
  const int fl = edge.left >= 0 ? facing[edge.left] : 0;
  const int fr = edge.right >= 0 ? facing[edge.right] : 0;
  bool culled = false;
  switch (edge.kind) {
    case EdgeKind::Flat:
      return 0;
    case EdgeKind::Smooth:
      if ((fl > 0) == (fr > 0) || solid.smooth_contours) return 0;  // not on the (polyhedral) contour
      [[fallthrough]];
    case EdgeKind::Feature: {
      const int front = (fl > 0) + (fr > 0);
      culled = cull && (front == 0 || (edge.concave && front == 1));
      break;
    }
    case EdgeKind::Marking:
    case EdgeKind::Hatch:
      culled = cull && fl <= 0;
      break;
    case EdgeKind::Boundary:
    case EdgeKind::Free:
      break;
  }
  if (culled && (!keep_culled || edge.kind == EdgeKind::Hatch)) return 0;
  return culled ? 2 : 1;
}

void count_edge_candidates(Room& room, const Solid& solid, const std::vector<std::int8_t>& facing, bool cull,
                           bool keep_culled, std::size_t edge_begin, std::size_t edge_end) {
  for (std::size_t e = edge_begin; e < edge_end; ++e)
    room.candidates += edge_use(solid, solid.edges[e], facing, cull, keep_culled) != 0;
}

// The candidates among edges [edge_begin, edge_end) of one object.
void add_edge_candidates(Slots& out, std::uint32_t o, const Solid& solid, const Point3* view_vertices,
                         const std::vector<std::int8_t>& facing, bool cull, bool keep_culled,
                         std::size_t edge_begin, std::size_t edge_end) {
  for (auto e = static_cast<std::uint32_t>(edge_begin); e < edge_end; ++e) {
    const SolidEdge& edge = solid.edges[e];
    const int use = edge_use(solid, edge, facing, cull, keep_culled);
    if (use == 0) continue;
    Candidate c;
    c.hatch = edge.kind == EdgeKind::Hatch;
    c.object = o;
    c.edge = e;
    c.own_face0 = edge.left;
    c.own_face1 = edge.right;
    c.view0 = view_vertices[edge.v0];
    c.view1 = view_vertices[edge.v1];
    c.culled = use == 2;
    out.candidates[out.candidate_count++] = c;
  }
}

// Near-plane clipping of candidates[0, count) (Desens' ALTER), projection and tolerances; drops what lies
// wholly behind the near plane, keeping the order. Returns how many are kept; `bounds` takes in their
// picture points.
std::size_t clip_and_project(Candidate* candidates, std::size_t count, const Camera& camera,
                             double length_tolerance, Rect2& bounds) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < count; ++i) {
    Candidate c = candidates[i];
    if (is_perspective(camera)) {
      const double near = camera.near_depth;
      const double z0 = c.view0.z, z1 = c.view1.z;
      if (z0 < near && z1 < near) continue;
      if (z0 < near || z1 < near) {
        const double t = (near - z0) / (z1 - z0);
        const Point3 v = lerp(c.view0, c.view1, t);
        if (z0 < near) {
          c.view0 = v;
          c.view0.z = near;
        } else {
          c.view1 = v;
          c.view1.z = near;
        }
      }
    }
    c.pic0 = camera.project_view(c.view0);
    c.pic1 = camera.project_view(c.view1);
    // Coordinates near the limits of double overflow; such a piece cannot be drawn or compared.
    if (!std::isfinite(c.pic0.x + c.pic0.y + c.pic1.x + c.pic1.y + c.view0.z + c.view1.z)) continue;
    set_picture_tolerance(c, camera, length_tolerance);
    bounds.include(c.pic0);
    bounds.include(c.pic1);
    candidates[kept++] = c;
  }
  return kept;
}

}  // namespace

FrameSetup prepare_frame(const Scene& scene, const Camera& camera, bool keep_culled, unsigned threads,
                         bool assume_uncrossed, BackFaces back_faces) {
  FrameSetup setup;
  setup.scene = &scene;
  const auto& m = camera.viewFromWorld.m;
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  setup.handedness = det < 0 ? -1 : 1;
  setup.length_tolerance = frame_tolerance(scene, camera).length;
  const double ltol = setup.length_tolerance;
  const ViewSide view{is_perspective(camera), is_perspective(camera) ? camera.eye_world() : Point3{},
                      camera.direction_world()};

  // Objects are independent: chunks of them are prepared in parallel, so the result does not depend on
  // the number of threads. A large object (a mesh of its own) is prepared in slices of its faces and
  // edges instead, once its view-space vertices and its faces' facing are known: its occluders and
  // candidates come out in the same order as in one piece. Each chunk first counts what it will add, then
  // writes it in place in the frame's lists: no part is grown, shrunk or copied (the bunny's set-up
  // copied 11.6 MB into fresh memory on one thread, 3–22 ms).
  const std::size_t n = scene.objects.size();
  std::vector<std::vector<std::int8_t>> facing(n);
  std::vector<char> cull(n, 0), clips(n, 0);
  const bool levels = back_faces == BackFaces::CountLevels;
  if (levels) keep_culled = true;
  const std::vector<char> meets_other = levels ? boxes_meeting_others(scene, ltol) : std::vector<char>(n, 0);
  // View-space vertices of every object, from view_base[o] on.
  std::vector<std::size_t> view_base(n + 1, 0);
  for (std::size_t o = 0; o < n; ++o)
    view_base[o + 1] = view_base[o] + scene.objects[o].solid->vertices.size();
  std::vector<Point3> view_points(view_base[n]);
  // The corner normals of the solids drawn with smooth contours (each solid's, kept with it).
  parallel_chunks(n, threads_for(n, 1, threads), [&](std::size_t o) {
    if (scene.objects[o].solid->smooth_contours) scene.objects[o].solid->corner_normals();
  });
  struct Job {
    std::size_t object_begin, object_end;  // whole objects; or one sliced object:
    std::size_t face_begin = 0, face_end = 0, edge_begin = 0, edge_end = 0;
    bool slice = false;
    Room room = {};
    std::vector<Candidate> contours = {};        // its objects' contour pieces (smooth contours), in order
    std::vector<std::size_t> contour_ends = {};  // per object of the job, the end of its pieces in `contours`
    Slots slots = {};
  };
  std::vector<Job> jobs;
  // Object o's view-space vertices, facing and culling, its vertices and faces shared out in `slices`.
  auto view_object = [&](std::size_t o, std::size_t slices, unsigned job_threads) {
    const Solid& solid = *scene.objects[o].solid;
    const std::size_t nv = solid.vertices.size(), nf = solid.faces.size();
    const std::span<Point3> view_vertices(view_points.data() + view_base[o], nv);
    facing[o].assign(nf, 0);
    parallel_chunks(slices, job_threads, [&](std::size_t k) {
      for (std::size_t i = nv * k / slices; i < nv * (k + 1) / slices; ++i)
        view_vertices[i] = camera.view(solid.vertices[i]);
      face_facing(solid, view, ltol, facing[o], nf * k / slices, nf * (k + 1) / slices);
    });
    // A closed solid's back faces hide nothing its front faces do not, and what lies on them is hidden —
    // while the surface never winds negatively round a point. A solid passing through itself may (a fold
    // in a scan turns a patch inside out), and so may one folded flat onto itself (Solid::folded), so
    // their back faces stay occluders and their back lines candidates.
    cull[o] = !meets_other[o] && solid.closed && !solid.folded &&
              wholly_in_front(view_vertices, camera, ltol) &&
              (assume_uncrossed || solid.self_crossings().empty());
    clips[o] = !wholly_in_front(view_vertices, camera, 0);
  };
  std::size_t faces = 0;
  for (const SceneObject& o : scene.objects) faces += o.solid->faces.size();
  // Preparing a face takes well under a microsecond: a few thousand are not worth sharing out.
  const unsigned frame_threads = threads_for(faces, 4096, threads);
  const std::size_t chunk = std::max<std::size_t>(1, n / 64);
  for (std::size_t o = 0; o < n;) {
    const Solid& solid = *scene.objects[o].solid;
    if (solid.faces.size() < kSliceFaces) {  // a run of small objects, up to `chunk` of them
      std::size_t end = o + 1;
      while (end < n && end - o < chunk && scene.objects[end].solid->faces.size() < kSliceFaces) ++end;
      jobs.push_back({o, end});
      o = end;
      continue;
    }
    const std::size_t slices =
        (std::max(solid.faces.size(), solid.edges.size()) + kSliceFaces - 1) / kSliceFaces;
    view_object(o, slices, frame_threads);
    for (std::size_t k = 0; k < slices; ++k)
      jobs.push_back({o, o + 1, solid.faces.size() * k / slices, solid.faces.size() * (k + 1) / slices,
                      solid.edges.size() * k / slices, solid.edges.size() * (k + 1) / slices, true});
    ++o;
  }
  // The ranges of faces and edges job `job` covers of its object `o`.
  auto faces_of = [](const Job& job, const Solid& solid) {
    return job.slice ? std::pair{job.face_begin, job.face_end}
                     : std::pair{std::size_t{0}, solid.faces.size()};
  };
  auto edges_of = [](const Job& job, const Solid& solid) {
    return job.slice ? std::pair{job.edge_begin, job.edge_end}
                     : std::pair{std::size_t{0}, solid.edges.size()};
  };
  // Counting: what each job adds at most (and its contour pieces, found now: they are few and not known
  // otherwise).
  parallel_chunks(jobs.size(), frame_threads, [&](std::size_t k) {
    Job& job = jobs[k];
    for (std::size_t o = job.object_begin; o < job.object_end; ++o) {
      const Solid& solid = *scene.objects[o].solid;
      if (!job.slice) view_object(o, 1, 1);
      const auto [face_begin, face_end] = faces_of(job, solid);
      const auto [edge_begin, edge_end] = edges_of(job, solid);
      count_occluders(job.room, solid, facing[o], cull[o], clips[o], face_begin, face_end);
      count_edge_candidates(job.room, solid, facing[o], cull[o], keep_culled, edge_begin, edge_end);
      if (solid.smooth_contours)
        add_contour_candidates(job.contours, static_cast<std::uint32_t>(o), solid, solid.corner_normals(),
                               camera, face_begin, face_end);
      job.contour_ends.push_back(job.contours.size());
    }
    job.room.candidates += job.contours.size();
  });
  Room total;
  for (Job& job : jobs) {
    job.slots.point_base = static_cast<std::uint32_t>(total.points);
    job.slots.ring_base = static_cast<std::uint32_t>(total.rings);
    total.occluders += job.room.occluders;
    total.points += job.room.points;
    total.rings += job.room.rings;
    total.candidates += job.room.candidates;
  }
  resize_touched(setup.occluders, total.occluders, frame_threads);
  resize_touched(setup.polygon_points, total.points, frame_threads);
  resize_touched(setup.polygon_seams, total.points, frame_threads);
  resize_touched(setup.ring_ends, total.rings, frame_threads);
  resize_touched(setup.candidates, total.candidates, frame_threads);
  {
    Room at;
    for (Job& job : jobs) {
      job.slots.occluders = setup.occluders.data() + at.occluders;
      job.slots.points = setup.polygon_points.data() + at.points;
      job.slots.seams = setup.polygon_seams.data() + at.points;
      job.slots.ring_ends = setup.ring_ends.data() + at.rings;
      job.slots.candidates = setup.candidates.data() + at.candidates;
      at.occluders += job.room.occluders;
      at.points += job.room.points;
      at.rings += job.room.rings;
      at.candidates += job.room.candidates;
    }
  }
  std::vector<Rect2> bounds(jobs.size(), Rect2::none());
  parallel_chunks(jobs.size(), frame_threads, [&](std::size_t k) {
    Job& job = jobs[k];
    Slots& out = job.slots;
    for (std::size_t o = job.object_begin; o < job.object_end; ++o) {
      const Solid& solid = *scene.objects[o].solid;
      const auto index = static_cast<std::uint32_t>(o);
      const Point3* view_vertices = view_points.data() + view_base[o];
      const auto [face_begin, face_end] = faces_of(job, solid);
      const auto [edge_begin, edge_end] = edges_of(job, solid);
      add_occluders(out, index, solid, view_vertices, facing[o], cull[o], camera, face_begin, face_end);
      add_edge_candidates(out, index, solid, view_vertices, facing[o], cull[o], keep_culled, edge_begin,
                          edge_end);
      const std::size_t i = o - job.object_begin;
      const auto from =
          job.contours.begin() + static_cast<std::ptrdiff_t>(i == 0 ? 0 : job.contour_ends[i - 1]);
      const auto to = job.contours.begin() + static_cast<std::ptrdiff_t>(job.contour_ends[i]);
      out.candidate_count = static_cast<std::size_t>(
          std::copy(from, to, out.candidates + out.candidate_count) - out.candidates);
    }
    out.candidate_count = clip_and_project(out.candidates, out.candidate_count, camera, ltol, bounds[k]);
    for (std::size_t i = 0; i < out.occluder_count; ++i) {
      Occluder& occ = out.occluders[i];
      const Rect2& b = occ.bounds;
      const double max_abs =
          std::max({std::abs(b.xmin), std::abs(b.xmax), std::abs(b.ymin), std::abs(b.ymax)});
      occ.picture_tolerance =
          Tolerance::picture(max_abs, camera.focal, ltol, view.perspective ? occ.min_depth : 1.0);
    }
  });
  release(view_points);
  // Where a job added less than it made room for (faces wholly behind the near plane, pieces clipped
  // away), what follows moves down, its point and ring numbers with it.
  Room at;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const Slots& job = jobs[k].slots;
    const std::size_t point_shift = job.point_base - at.points, ring_shift = job.ring_base - at.rings;
    Occluder* occluders = setup.occluders.data() + at.occluders;
    if (occluders != job.occluders || point_shift != 0 || ring_shift != 0) {
      for (std::size_t i = 0; i < job.occluder_count; ++i) {
        occluders[i] = job.occluders[i];
        occluders[i].first_point -= static_cast<std::uint32_t>(point_shift);
        occluders[i].first_ring -= static_cast<std::uint32_t>(ring_shift);
      }
      std::copy_n(job.points, job.point_count, setup.polygon_points.data() + at.points);
      std::copy_n(job.seams, job.point_count, setup.polygon_seams.data() + at.points);
      for (std::size_t i = 0; i < job.ring_count; ++i)
        setup.ring_ends[at.rings + i] = job.ring_ends[i] - static_cast<std::uint32_t>(point_shift);
    }
    if (job.candidates != setup.candidates.data() + at.candidates)
      std::copy_n(job.candidates, job.candidate_count, setup.candidates.data() + at.candidates);
    at.occluders += job.occluder_count;
    at.points += job.point_count;
    at.rings += job.ring_count;
    at.candidates += job.candidate_count;
    if (!bounds[k].empty()) {
      setup.picture_bounds.include({bounds[k].xmin, bounds[k].ymin});
      setup.picture_bounds.include({bounds[k].xmax, bounds[k].ymax});
    }
  }
  setup.occluders.resize(at.occluders);
  setup.polygon_points.resize(at.points);
  setup.polygon_seams.resize(at.points);
  setup.ring_ends.resize(at.rings);
  setup.candidates.resize(at.candidates);

  // Grids over the rings of large occluders, made once the points are where they stay.
  std::vector<std::uint32_t> ends;
  for (Occluder& o : setup.occluders) {
    const std::uint32_t count = setup.ring_ends[o.first_ring + o.ring_count - 1] - o.first_point;
    if (count < RingEdgeGrid::kMinPoints) continue;
    ends.clear();
    for (std::uint32_t r = 0; r < o.ring_count; ++r)
      ends.push_back(setup.ring_ends[o.first_ring + r] - o.first_point);
    o.grid = static_cast<std::int32_t>(setup.ring_grids.size());
    setup.ring_grids.emplace_back(std::span<const Point2>(setup.polygon_points.data() + o.first_point, count),
                                  ends);
  }
  setup.facing = std::move(facing);
  setup.cull = std::move(cull);
  return setup;
}

void append_intersection_candidates(FrameSetup& setup, const Scene& scene, const Camera& camera,
                                    bool keep_culled) {
  // Collected apart and appended at their exact count, so the large candidate list grows once.
  FrameSetup crossings;
  add_intersection_candidates(scene, camera, setup.facing, setup.cull, setup.length_tolerance, keep_culled,
                              crossings);
  crossings.candidates.resize(clip_and_project(crossings.candidates.data(), crossings.candidates.size(),
                                               camera, setup.length_tolerance, setup.picture_bounds));
  if (crossings.candidates.empty()) return;
  setup.candidates.reserve(setup.candidates.size() + crossings.candidates.size());
  setup.candidates.insert(setup.candidates.end(), crossings.candidates.begin(), crossings.candidates.end());
}

}  // namespace hlr
