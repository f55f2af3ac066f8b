// Blender's Line Art beside our drawing and the tests' ray-casting oracle (tracker issue 36; README.md
// beside this file). Reads a mesh with our importer, our camera, and the strokes blender_lineart.py wrote
// for the same mesh and camera, and reports:
//   * the visible length (picture units) of Line Art's strokes and of our render_frame() pieces;
//   * Line Art's false-visible share: of its stroke length, sampled, the share the oracle calls Hidden
//     (Ambiguous samples are left out of the share and counted apart); its float points are first put
//     back on the mesh edge they lie on (EdgeGrid), and the share on edges we call Flat is reported;
//   * Line Art's missing share: of our visible length, sampled, the share no Line Art stroke passes within
//     D of on the picture (D = a fraction of the picture extent, the diagonal of our drawing's bounding
//     box; 1e-3 and 1e-4 are reported);
//   * the same two for our drawing against the oracle: of our visible length the share it calls Hidden,
//     and of the drawn-candidate edges' length the oracle calls Visible (sampled) the share no piece of
//     ours passes within D of — and, on that same oracle sample, Line Art's missing share too;
//   * our hidden-line time for the mesh and camera: the median of N render_frame() calls on a fresh copy
//     of the solid each time (so its self-crossings are searched every time, as Line Art computes its
//     intersections on every evaluation), and with the crossings kept (an animation's later frames).
//
//   lineart_compare MESH --strokes strokes.json --eye X Y Z --target X Y Z [--up X Y Z]
//       (--fov DEG | --ortho-height H) [--aspect A] [--crease DEG] [--runs N] [--samples N]
//       [--coverage-samples N] [--json]
// --samples: points judged by the oracle per figure (default 10 000; each is a ray against every face);
// --coverage-samples: points for the picture-distance figures (default 200 000).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/mesh_import.hpp"
#include "tests/support/ray_caster.hpp"
#include "tests/support/ray_caster_checks.hpp"

namespace {

using namespace hlr;

struct Options {
  std::string mesh, strokes;
  Point3 eye{}, target{};
  Vector3 up{0, 0, 1};
  double fov = 40, ortho_height = 0, aspect = 273.0 / 186.0, crease = 0;
  int runs = 5;
  std::size_t samples = 10000;            // judged by the oracle (a ray against every face each)
  std::size_t coverage_samples = 200000;  // for the picture-distance figures (cheap)
  bool json = false;
};

// A piece of a line with its world ends (for the oracle) and picture ends (for coverage).
struct Piece {
  Point3 p0, p1;
  Point2 s0, s1;
  double length() const { return std::hypot(s1.x - s0.x, s1.y - s0.y); }
};

struct Sample {
  Point3 world;
  Point2 picture;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double total_length(const std::vector<Piece>& pieces) {
  double sum = 0;
  for (const Piece& p : pieces) sum += p.length();
  return sum;
}

// `n` samples spread evenly over the pieces' total picture length (stratified: the k-th at (k + ½)/n of
// it). A sample at fraction t of its piece's picture length is taken at fraction t of the piece in the
// world and projected again: world and picture point agree (in perspective it is then not exactly at t
// on the picture).
std::vector<Sample> spread(const std::vector<Piece>& pieces, std::size_t n, const Camera& camera) {
  std::vector<Sample> out;
  const double total = total_length(pieces);
  if (total <= 0 || n == 0) return out;
  const double step = total / static_cast<double>(n);
  double next = 0.5 * step, start = 0;
  for (const Piece& p : pieces) {
    const double len = p.length();
    while (next < start + len && out.size() < n) {
      const double t = (next - start) / len;
      const Point3 w{p.p0.x + t * (p.p1.x - p.p0.x), p.p0.y + t * (p.p1.y - p.p0.y),
                     p.p0.z + t * (p.p1.z - p.p0.z)};
      out.push_back({w, camera.project(w)});
      next += step;
    }
    start += len;
  }
  return out;
}

// Picture segments in a uniform grid: the distance from a point to the nearest one, up to `reach`.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Piece>& pieces, double reach) : pieces_(pieces), reach_(reach) {
    lo_ = {1e300, 1e300};
    Point2 hi{-1e300, -1e300};
    for (const Piece& p : pieces) {
      for (Point2 s : {p.s0, p.s1}) {
        lo_ = {std::min(lo_.x, s.x), std::min(lo_.y, s.y)};
        hi = {std::max(hi.x, s.x), std::max(hi.y, s.y)};
      }
    }
    if (pieces.empty()) return;
    lo_ = {lo_.x - reach, lo_.y - reach};
    hi = {hi.x + reach, hi.y + reach};
    const double w = hi.x - lo_.x, h = hi.y - lo_.y;
    // About one piece per cell, never cells smaller than the reach (a query then reads one cell).
    cell_ = std::max(reach, std::sqrt(w * h / static_cast<double>(pieces.size())));
    nx_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(w / cell_)));
    ny_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(h / cell_)));
    cells_.resize(nx_ * ny_);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      const auto [x0, y0] = cell_of({std::min(p.s0.x, p.s1.x) - reach, std::min(p.s0.y, p.s1.y) - reach});
      const auto [x1, y1] = cell_of({std::max(p.s0.x, p.s1.x) + reach, std::max(p.s0.y, p.s1.y) + reach});
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x)
          // Long pieces across many cells: keep only the cells the piece passes within reach of.
          if ((x1 - x0 < 2 && y1 - y0 < 2) || crosses_cell(p, x, y)) cells_[y * nx_ + x].push_back(i);
    }
  }

  // Distance to the nearest piece when one is within `reach`, else infinity.
  double distance(Point2 q) const {
    const double none = std::numeric_limits<double>::infinity();
    if (cells_.empty() || q.x < lo_.x || q.y < lo_.y) return none;
    const auto [x, y] = cell_of(q);
    if (x >= nx_ || y >= ny_) return none;
    double best = none;
    for (std::size_t i : cells_[y * nx_ + x]) {
      const Piece& p = pieces_[i];
      best = std::min(best, test::point_segment_distance(q, p.s0, p.s1));
    }
    return best <= reach_ ? best : none;
  }

 private:
  std::pair<std::size_t, std::size_t> cell_of(Point2 q) const {
    const auto clamp = [](double v, std::size_t n) {
      return static_cast<std::size_t>(std::clamp(v, 0.0, static_cast<double>(n - 1)));
    };
    return {clamp(std::floor((q.x - lo_.x) / cell_), nx_), clamp(std::floor((q.y - lo_.y) / cell_), ny_)};
  }
  bool crosses_cell(const Piece& p, std::size_t x, std::size_t y) const {
    const Point2 c{lo_.x + (static_cast<double>(x) + 0.5) * cell_,
                   lo_.y + (static_cast<double>(y) + 0.5) * cell_};
    return test::point_segment_distance(c, p.s0, p.s1) <= cell_ * std::sqrt(0.5) + reach_;
  }

  const std::vector<Piece>& pieces_;
  double reach_, cell_ = 1;
  Point2 lo_{};
  std::size_t nx_ = 0, ny_ = 0;
  std::vector<std::vector<std::size_t>> cells_;
};

// The solid's edges in a uniform 3-D grid, to put Line Art's points back on the edge they lie on: its
// strokes are floats (≈ 10⁻⁷ of the coordinates off the edge), which the oracle, whose faces must contain
// a point to rounding (10⁻¹⁰ of the extent) to let it lie on them, would call Ambiguous.
class EdgeGrid {
 public:
  EdgeGrid(const Solid& solid) : solid_(solid) {
    std::vector<double> lengths;
    lo_ = hi_ = solid.vertices.front();
    for (Point3 p : solid.vertices) {
      lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
      hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y), std::max(hi_.z, p.z)};
    }
    for (const SolidEdge& e : solid.edges)
      lengths.push_back(hlr::distance(solid.vertices[e.v0], solid.vertices[e.v1]));
    cell_ = std::max(2 * median(lengths), 1e-9 * hlr::distance(lo_, hi_));
    for (int k = 0; k < 3; ++k)
      n_[k] = static_cast<std::size_t>(std::floor((coord(hi_, k) - coord(lo_, k)) / cell_)) + 1;
    cells_.resize(n_[0] * n_[1] * n_[2]);
    for (std::size_t i = 0; i < solid.edges.size(); ++i) {
      const Point3 a = solid.vertices[solid.edges[i].v0], b = solid.vertices[solid.edges[i].v1];
      std::array<std::size_t, 3> c0{}, c1{};
      for (int k = 0; k < 3; ++k) {
        c0[k] = index(std::min(coord(a, k), coord(b, k)), k);
        c1[k] = index(std::max(coord(a, k), coord(b, k)), k);
      }
      for (std::size_t z = c0[2]; z <= c1[2]; ++z)
        for (std::size_t y = c0[1]; y <= c1[1]; ++y)
          for (std::size_t x = c0[0]; x <= c1[0]; ++x) cells_[(z * n_[1] + y) * n_[0] + x].push_back(i);
    }
  }

  // The nearest point on an edge within `reach` (< the cell size) of p, and that edge; nullopt if none.
  std::optional<std::pair<Point3, std::size_t>> snap(Point3 p, double reach) const {
    std::array<std::size_t, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = index(coord(p, k), k);
    double best = reach;
    std::optional<std::pair<Point3, std::size_t>> found;
    for (std::size_t z = c[2] ? c[2] - 1 : 0; z <= std::min(c[2] + 1, n_[2] - 1); ++z)
      for (std::size_t y = c[1] ? c[1] - 1 : 0; y <= std::min(c[1] + 1, n_[1] - 1); ++y)
        for (std::size_t x = c[0] ? c[0] - 1 : 0; x <= std::min(c[0] + 1, n_[0] - 1); ++x)
          for (std::size_t i : cells_[(z * n_[1] + y) * n_[0] + x]) {
            const Point3 a = solid_.vertices[solid_.edges[i].v0], b = solid_.vertices[solid_.edges[i].v1];
            const Vector3 ab = b - a;
            const double t = std::clamp(dot(p - a, ab) / std::max(dot(ab, ab), 1e-300), 0.0, 1.0);
            const Point3 q = a + t * ab;
            const double d = hlr::distance(p, q);
            if (d <= best) best = d, found = std::pair{q, i};
          }
    return found;
  }

 private:
  static double coord(Point3 p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }
  std::size_t index(double v, int k) const {
    const double i = std::floor((v - coord(lo_, k)) / cell_);
    return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(n_[k] - 1)));
  }

  const Solid& solid_;
  Point3 lo_{}, hi_{};
  double cell_ = 1;
  std::array<std::size_t, 3> n_{};
  std::vector<std::vector<std::size_t>> cells_;
};

// The oracle's verdict on every sample, on every core.
std::vector<test::Visibility> classify(const test::RayCaster& oracle, const std::vector<Sample>& samples) {
  std::vector<test::Visibility> out(samples.size());
  const unsigned n = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> workers;
  for (unsigned w = 0; w < n; ++w)
    workers.emplace_back([&, w] {
      for (std::size_t i = w; i < samples.size(); i += n) out[i] = oracle.visibility(samples[i].world);
    });
  for (std::thread& t : workers) t.join();
  return out;
}

struct Share {
  std::size_t counted = 0, hit = 0, ambiguous = 0;
  double share() const { return counted ? static_cast<double>(hit) / static_cast<double>(counted) : 0; }
};

Share hidden_share(const std::vector<test::Visibility>& verdicts) {
  Share s;
  for (test::Visibility v : verdicts) {
    if (v == test::Visibility::Ambiguous) {
      ++s.ambiguous;
      continue;
    }
    ++s.counted;
    s.hit += v == test::Visibility::Hidden;
  }
  return s;
}

// Of the samples (those the mask keeps), the share farther than `d` from every piece of `grid`.
Share uncovered_share(const SegmentGrid& grid, const std::vector<Sample>& samples, double d,
                      const std::vector<bool>* keep = nullptr) {
  Share s;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (keep && !(*keep)[i]) continue;
    ++s.counted;
    s.hit += grid.distance(samples[i].picture) > d;
  }
  return s;
}

std::vector<Piece> read_strokes(const std::string& path, const Camera& camera, std::size_t& strokes,
                                std::size_t& behind, nlohmann::json& timing) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const nlohmann::json j = nlohmann::json::parse(in);
  if (j.value("format", "") != "hlrscript.lineart/1")
    throw std::runtime_error(path + ": not hlrscript.lineart/1");
  timing = j.value("timing", nlohmann::json::object());
  std::vector<Piece> pieces;
  strokes = j.at("strokes").size();
  behind = 0;
  for (const nlohmann::json& stroke : j.at("strokes")) {
    for (std::size_t i = 1; i < stroke.size(); ++i) {
      const Point3 a{stroke[i - 1][0].get<double>(), stroke[i - 1][1].get<double>(),
                     stroke[i - 1][2].get<double>()};
      const Point3 b{stroke[i][0].get<double>(), stroke[i][1].get<double>(), stroke[i][2].get<double>()};
      if (camera.projection == Projection::Perspective &&
          (camera.view(a).z <= camera.near_depth || camera.view(b).z <= camera.near_depth)) {
        ++behind;
        continue;
      }
      pieces.push_back({a, b, camera.project(a), camera.project(b)});
    }
  }
  return pieces;
}

struct Box2 {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void include(Point2 p) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  double diagonal() const { return std::hypot(x1 - x0, y1 - y0); }
};

Box2 bounds(const std::vector<Piece>& pieces) {
  Box2 b;
  for (const Piece& p : pieces) b.include(p.s0), b.include(p.s1);
  return b;
}

// Median render_frame() time (seconds): `fresh` copies the solid before each run (not timed), so the
// self-crossing search is in every run; otherwise one untimed warm-up finds them and the runs reuse them.
double time_ours(const Solid& solid, const Camera& camera, unsigned threads, int runs, bool fresh,
                 FrameResult& last) {
  HlrOptions options;
  options.threads = threads;
  Scene kept;
  kept.objects.push_back({"mesh", std::make_shared<const Solid>(solid)});
  if (!fresh) last = render_frame(kept, camera, options);
  std::vector<double> times;
  for (int i = 0; i < runs; ++i) {
    Scene scene;
    if (fresh)
      scene.objects.push_back({"mesh", std::make_shared<const Solid>(solid)});
    else
      scene = kept;
    const auto t0 = std::chrono::steady_clock::now();
    last = render_frame(scene, camera, options);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median(times);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> double {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return std::stod(argv[++i]);
    };
    auto point = [&]() -> Point3 {
      const double x = value(), y = value(), z = value();
      return {x, y, z};
    };
    if (a == "--strokes" && i + 1 < argc) {
      o.strokes = argv[++i];
    } else if (a == "--eye") {
      o.eye = point();
    } else if (a == "--target") {
      o.target = point();
    } else if (a == "--up") {
      const Point3 u = point();
      o.up = {u.x, u.y, u.z};
    } else if (a == "--fov") {
      o.fov = value();
    } else if (a == "--ortho-height") {
      o.ortho_height = value();
    } else if (a == "--aspect") {
      o.aspect = value();
    } else if (a == "--crease") {
      o.crease = value();
    } else if (a == "--runs") {
      o.runs = std::max(1, static_cast<int>(value()));
    } else if (a == "--samples") {
      o.samples = static_cast<std::size_t>(std::max(1.0, value()));
    } else if (a == "--coverage-samples") {
      o.coverage_samples = static_cast<std::size_t>(std::max(1.0, value()));
    } else if (a == "--json") {
      o.json = true;
    } else if (!a.starts_with("-") && o.mesh.empty()) {
      o.mesh = a;
    } else {
      throw std::invalid_argument("unknown argument " + a);
    }
  }
  if (o.mesh.empty() || o.strokes.empty()) throw std::invalid_argument("a mesh and --strokes are needed");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  try {
    opt = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(
        stderr,
        "%s\nusage: lineart_compare MESH --strokes strokes.json --eye X Y Z --target X Y Z [--up X Y Z] "
        "(--fov DEG | --ortho-height H) [--aspect A] [--crease DEG] [--runs N] [--samples N] "
        "[--coverage-samples N] [--json]\n",
        e.what());
    return 2;
  }
  try {
    stdlib::MeshImportOptions import_options;
    import_options.crease_angle_deg = opt.crease;
    const Solid solid = stdlib::import_mesh(opt.mesh, import_options).solid;
    // The picture window our PDF gives the camera: `aspect` wide, 2 high (hlrscript's default page).
    const Camera camera = opt.ortho_height > 0
                              ? ortho_camera({opt.eye, opt.target, opt.up, opt.ortho_height, 0})
                              : lookat_camera({opt.eye, opt.target, opt.up, opt.fov, 0, 0});
    Scene scene;
    scene.objects.push_back({"mesh", std::make_shared<const Solid>(solid)});

    // Our drawing and its times (every core, then one thread; fresh solids, then crossings kept).
    FrameResult result;
    const double cold_all = time_ours(solid, camera, 0, opt.runs, true, result);
    const double cold_one = time_ours(solid, camera, 1, opt.runs, true, result);
    const double warm_all = time_ours(solid, camera, 0, opt.runs, false, result);
    std::vector<Piece> ours;
    std::size_t ours_intersection = 0;
    for (const VisibleSegment& s : result.segments) {
      if (s.hidden) continue;
      ours.push_back({s.p0, s.p1, s.s0, s.s1});
      ours_intersection += s.source == SegmentSource::Intersection;
    }

    std::size_t strokes = 0, behind = 0;
    nlohmann::json timing;
    const std::vector<Piece> theirs = read_strokes(opt.strokes, camera, strokes, behind, timing);

    const Box2 ours_box = bounds(ours), theirs_box = bounds(theirs);
    const double extent = ours_box.diagonal();
    const std::vector<double> fractions = {1e-3, 1e-4};
    const double d_max = fractions.front() * extent;
    const SegmentGrid ours_grid(ours, d_max), theirs_grid(theirs, d_max);

    // Drawn-candidate edges (Feature, Boundary; Smooth ones on the contour), for the oracle's own sample.
    const test::RayCaster oracle(scene, camera);
    std::vector<Piece> candidates;
    for (const SolidEdge& e : solid.edges) {
      if (test::drawn_candidate(oracle, 0, solid, e) != test::Candidate::Yes) continue;
      const Point3 a = solid.vertices[e.v0], b = solid.vertices[e.v1];
      if (camera.projection == Projection::Perspective &&
          (camera.view(a).z <= camera.near_depth || camera.view(b).z <= camera.near_depth))
        continue;
      candidates.push_back({a, b, camera.project(a), camera.project(b)});
    }

    const auto t_oracle = std::chrono::steady_clock::now();
    // Line Art's samples put back on the mesh edge each lies on (within 10⁻⁵ of the mesh's diagonal);
    // those on no edge (intersection lines, or not on the mesh) are judged where they are.
    const EdgeGrid edge_grid(solid);
    Point3 mesh_lo = solid.vertices.front(), mesh_hi = mesh_lo;
    for (Point3 p : solid.vertices) {
      mesh_lo = {std::min(mesh_lo.x, p.x), std::min(mesh_lo.y, p.y), std::min(mesh_lo.z, p.z)};
      mesh_hi = {std::max(mesh_hi.x, p.x), std::max(mesh_hi.y, p.y), std::max(mesh_hi.z, p.z)};
    }
    const double snap_reach = 1e-5 * distance(mesh_lo, mesh_hi);
    std::size_t off_edge = 0, on_flat = 0;
    const auto snap_all = [&](std::vector<Sample> samples, bool count) {
      for (Sample& sample : samples) {
        const auto snapped = edge_grid.snap(sample.world, snap_reach);
        if (!snapped) {
          off_edge += count;
          continue;
        }
        on_flat += count && solid.edges[snapped->second].kind == EdgeKind::Flat;
        sample = {snapped->first, camera.project(snapped->first)};
      }
      return samples;
    };
    const std::vector<Sample> theirs_samples = snap_all(spread(theirs, opt.samples, camera), false);
    const std::vector<Sample> theirs_dense = snap_all(spread(theirs, opt.coverage_samples, camera), true);
    const std::vector<Sample> ours_dense = spread(ours, opt.coverage_samples, camera);
    const std::vector<Sample> ours_samples = spread(ours, opt.samples, camera);
    const std::vector<Sample> edge_samples = spread(candidates, opt.samples, camera);
    const Share theirs_hidden = hidden_share(classify(oracle, theirs_samples));
    const Share ours_hidden = hidden_share(classify(oracle, ours_samples));
    const std::vector<test::Visibility> edge_verdicts = classify(oracle, edge_samples);
    std::vector<bool> edge_visible(edge_samples.size());
    std::size_t edge_ambiguous = 0;
    for (std::size_t i = 0; i < edge_samples.size(); ++i) {
      edge_visible[i] = edge_verdicts[i] == test::Visibility::Visible;
      edge_ambiguous += edge_verdicts[i] == test::Visibility::Ambiguous;
    }
    const double oracle_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_oracle).count();

    nlohmann::json out;
    out["mesh"] = opt.mesh;
    out["faces"] = solid.faces.size();
    out["distance_basis"] = "fraction of the picture extent (diagonal of our drawing's bounding box)";
    out["picture_extent"] = extent;
    out["ours"] = {{"visible_length", total_length(ours)},
                   {"pieces", ours.size()},
                   {"intersection_pieces", ours_intersection},
                   {"hlr_fresh_all_threads_s", cold_all},
                   {"hlr_fresh_one_thread_s", cold_one},
                   {"hlr_kept_crossings_all_threads_s", warm_all},
                   {"bbox", {ours_box.x0, ours_box.y0, ours_box.x1, ours_box.y1}},
                   {"false_visible", ours_hidden.share()},
                   {"false_visible_ambiguous", ours_hidden.ambiguous},
                   {"samples", ours_samples.size()}};
    out["lineart"] = {
        {"visible_length", total_length(theirs)},
        {"strokes", strokes},
        {"segments", theirs.size()},
        {"segments_behind_eye", behind},
        {"bbox", {theirs_box.x0, theirs_box.y0, theirs_box.x1, theirs_box.y1}},
        {"false_visible", theirs_hidden.share()},
        {"false_visible_ambiguous", theirs_hidden.ambiguous},
        {"dense_samples", theirs_dense.size()},
        {"share_on_no_edge", static_cast<double>(off_edge) / std::max<double>(1, theirs_dense.size())},
        {"share_on_flat_edges", static_cast<double>(on_flat) / std::max<double>(1, theirs_dense.size())},
        {"samples", theirs_samples.size()},
        {"timing", timing}};
    out["oracle"] = {{"candidate_edges", candidates.size()},
                     {"edge_samples", edge_samples.size()},
                     {"edge_samples_visible", std::count(edge_visible.begin(), edge_visible.end(), true)},
                     {"edge_samples_ambiguous", edge_ambiguous},
                     {"seconds", oracle_s}};
    for (double f : fractions) {
      const double d = f * extent;
      char key[32];
      std::snprintf(key, sizeof key, "%.0e", f);
      out["missing"][key] = {
          {"lineart_vs_ours", uncovered_share(theirs_grid, ours_dense, d).share()},
          {"lineart_not_in_ours", uncovered_share(ours_grid, theirs_dense, d).share()},
          {"lineart_vs_oracle", uncovered_share(theirs_grid, edge_samples, d, &edge_visible).share()},
          {"ours_vs_oracle", uncovered_share(ours_grid, edge_samples, d, &edge_visible).share()}};
    }

    if (opt.json) {
      std::printf("%s\n", out.dump().c_str());
      return 0;
    }
    const auto& o = out["ours"];
    const auto& l = out["lineart"];
    std::printf("%s: %zu faces, picture extent %.6g (our drawing's bounding-box diagonal)\n",
                opt.mesh.c_str(), solid.faces.size(), extent);
    std::printf(
        "ours:     visible length %.6f (%zu pieces, %zu of intersection lines); bbox [%.4f, %.4f] x [%.4f, "
        "%.4f]\n",
        o["visible_length"].get<double>(), ours.size(), ours_intersection, ours_box.x0, ours_box.x1,
        ours_box.y0, ours_box.y1);
    std::printf(
        "Line Art: visible length %.6f (%zu strokes, %zu segments, %zu behind the eye); bbox [%.4f, %.4f] x "
        "[%.4f, %.4f]\n",
        l["visible_length"].get<double>(), strokes, theirs.size(), behind, theirs_box.x0, theirs_box.x1,
        theirs_box.y0, theirs_box.y1);
    std::printf(
        "our hidden lines: %.1f ms (every core), %.1f ms (one thread), %.1f ms (crossings kept), medians of "
        "%d\n",
        1e3 * cold_all, 1e3 * cold_one, 1e3 * warm_all, opt.runs);
    if (timing.contains("lineart_median_s") && timing["lineart_median_s"].is_number())
      std::printf("Line Art evaluation (median, from the strokes file): %.1f ms: %.3g x ours\n",
                  1e3 * timing["lineart_median_s"].get<double>(),
                  timing["lineart_median_s"].get<double>() / cold_all);
    std::printf(
        "false-visible (oracle Hidden, of the drawn length): Line Art %.4f%% (%zu ambiguous of %zu), ours "
        "%.4f%% "
        "(%zu ambiguous of %zu)\n",
        1e2 * theirs_hidden.share(), theirs_hidden.ambiguous, theirs_samples.size(),
        1e2 * ours_hidden.share(), ours_hidden.ambiguous, ours_samples.size());
    std::printf(
        "Line Art's length on no mesh edge (within %.3g): %.4f%%, on edges we call Flat (coplanar faces): "
        "%.4f%% (%zu samples)\n",
        snap_reach, 1e2 * static_cast<double>(off_edge) / std::max<double>(1, theirs_dense.size()),
        1e2 * static_cast<double>(on_flat) / std::max<double>(1, theirs_dense.size()), theirs_dense.size());
    std::printf(
        "oracle sample: %zu candidate edges, %zu samples, %ld visible, %zu ambiguous (%.1f s of ray "
        "casting)\n",
        candidates.size(), edge_samples.size(),
        static_cast<long>(std::count(edge_visible.begin(), edge_visible.end(), true)), edge_ambiguous,
        oracle_s);
    for (auto it = out["missing"].begin(); it != out["missing"].end(); ++it) {
      const auto& m = it.value();
      std::printf(
          "within %s of the extent: Line Art misses %.4f%% of ours, draws %.4f%% not in ours; of the "
          "oracle's "
          "visible edge samples Line Art misses %.4f%%, ours %.4f%%\n",
          it.key().c_str(), 1e2 * m["lineart_vs_ours"].get<double>(),
          1e2 * m["lineart_not_in_ours"].get<double>(), 1e2 * m["lineart_vs_oracle"].get<double>(),
          1e2 * m["ours_vs_oracle"].get<double>());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lineart_compare: %s\n", e.what());
    return 1;
  }
}
