// More solid generators (stdlib/shapes.hpp): pyramids, the Platonic solids, cones, extrusions, surfaces of
// revolution, sweeps and heightfields. As in builtins_solids.cpp, this file only checks arguments and
// charges the face budget; the stdlib does the geometry and its invalid_argument messages (which name the
// parameter as the script does) become errors at the call.
#include <cmath>
#include <optional>
#include <string>

#include "core/format_number.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);
constexpr KindSet kList = kinds(ValueKind::List);
constexpr int kMaxCount = static_cast<int>(kMaxFaces);

// A list of at least `min` points.
std::vector<Point3> points_arg(const Bound& b, std::size_t i, std::size_t min) {
  const std::vector<Vector3> vs = b.vectors(i);
  if (vs.size() < min)
    b.fail(i, "needs at least " + std::to_string(min) + " points, got " + std::to_string(vs.size()));
  std::vector<Point3> out;
  out.reserve(vs.size());
  for (const Vector3& v : vs) out.push_back(to_point(v));
  return out;
}

// Points of a plane curve given as vectors: (x, y, 0) in the xy plane (`drop` = 2), or (r, 0, z) in the
// x–z plane (`drop` = 1).
std::vector<Point2> plane_points_arg(const Bound& b, std::size_t i, std::size_t min, int drop) {
  const std::vector<Point3> ps = points_arg(b, i, min);
  std::vector<Point2> out;
  out.reserve(ps.size());
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double off = drop == 2 ? ps[k].z : ps[k].y;
    if (off != 0)
      b.fail(i, "point " + std::to_string(k) + " has " + (drop == 2 ? "z" : "y") + " = " +
                    format_for_message(off) +
                    (drop == 2 ? "; outlines lie in the xy plane (z = 0)"
                               : "; a profile lies in the x-z plane: (r, 0, z)"));
    out.push_back(drop == 2 ? Point2{ps[k].x, ps[k].y} : Point2{ps[k].x, ps[k].z});
  }
  return out;
}

const ParamList kPyramidParams = {required("outline", kList), required("apex", kVector)};

Value pyramid_(CallArgs& call) {
  const Bound b = call.bind(kPyramidParams);
  const std::vector<Point3> outline = points_arg(b, 0, 3);
  const Point3 apex = b.point(1);
  return generated_solid(call, outline.size() + 1, [&] { return stdlib::pyramid(outline, apex); });
}

// Every Platonic solid binds this one list.
const ParamList kPlatonicParams = {optional("r", kNumber, Value::number(1))};

template <Solid (*Make)(double)>
Value platonic_(CallArgs& call) {
  const Bound b = call.bind(kPlatonicParams);
  const double r = b.positive(0);
  return generated_solid(call, 20, [&] { return Make(r); });
}

const ParamList kConeParams = {required("r", kNumber),
                               required("h", kNumber),
                               optional("top", kNumber, Value::number(0)),
                               optional("sides", kNumber, Value::number(32)),
                               crease_param(),
                               contours_param()};

Value cone_(CallArgs& call) {
  const Bound b = call.bind(kConeParams);
  const double r = b.non_negative(0), h = b.positive(1), top = b.non_negative(2);
  if (r == 0 && top == 0) b.fail(0, "and top cannot both be 0");
  const int sides = b.whole(3, 3, kMaxCount);
  const double deg = crease_angle(b, 4);
  const bool smooth = smooth_contours(b, 5);
  return generated_solid(call, static_cast<std::size_t>(sides) + 2,
                         [&] { return with_contours(stdlib::cone(r, h, top, sides, deg), smooth); });
}

const ParamList kExtrudeParams = {required("outline", kList), required("v", kVector),
                                  optional("holes", kList, Value::list({}))};

Value extrude_(CallArgs& call) {
  const Bound b = call.bind(kExtrudeParams);
  const std::vector<Point3> outline = points_arg(b, 0, 3);
  const Vector3 v = b.vector(1);
  std::vector<std::vector<Point3>> holes;
  std::size_t faces = outline.size() + 2;
  for_each_sublist(call, b, 2, "holes", "hole", "a list of points", [&](const Bound& one, std::size_t) {
    holes.push_back(points_arg(one, 0, 3));
    faces += holes.back().size();
  });
  return generated_solid(call, faces, [&] { return stdlib::extrude(outline, v, holes); });
}

const ParamList kRevolveParams = {
    required("profile", kList), optional("segments", kNumber, Value::number(32)),
    optional("angle", kNumber, Value::number(360)), crease_param(), contours_param()};

Value revolve_(CallArgs& call) {
  const Bound b = call.bind(kRevolveParams);
  const std::vector<Point2> profile = plane_points_arg(b, 0, 2, 1);
  const int segments = b.whole(1, 1, kMaxCount);
  const double angle = b.positive(2);
  const double deg = crease_angle(b, 3);
  const bool smooth = smooth_contours(b, 4);
  const std::size_t faces = static_cast<std::size_t>(segments) * profile.size() + 2;
  return generated_solid(
      call, faces, [&] { return with_contours(stdlib::revolve(profile, segments, angle, deg), smooth); });
}

const ParamList kSweepParams = {required("profile", kList), required("path", kList), crease_param(),
                                contours_param()};

Value sweep_(CallArgs& call) {
  const Bound b = call.bind(kSweepParams);
  const std::vector<Point2> profile = plane_points_arg(b, 0, 3, 2);
  const std::vector<Point3> path = points_arg(b, 1, 2);
  const double deg = crease_angle(b, 2);
  const bool smooth = smooth_contours(b, 3);
  const std::size_t faces = profile.size() * path.size() + 2;
  return generated_solid(call, faces,
                         [&] { return with_contours(stdlib::sweep(profile, path, deg), smooth); });
}

const ParamList kHeightfieldParams = {required("values", kList),
                                      optional("dx", kNumber, Value::number(1)),
                                      optional("dy", kNumber, Value::number(1)),
                                      optional("base", kNumber),
                                      crease_param(),
                                      contours_param()};

Value heightfield_(CallArgs& call) {
  const Bound b = call.bind(kHeightfieldParams);
  std::vector<std::vector<double>> rows;
  std::size_t cells = 0;
  for_each_sublist(call, b, 0, "values", "row", "a list of heights", [&](const Bound& one, std::size_t) {
    rows.push_back(one.numbers(0));
    cells += rows.back().size();
  });
  const double dx = b.positive(1), dy = b.positive(2);
  const std::optional<double> base = b.present(3) ? std::optional<double>(b.number(3)) : std::nullopt;
  const double deg = crease_angle(b, 4);
  const bool smooth = smooth_contours(b, 5);
  return generated_solid(call, 2 * cells + 5,
                         [&] { return with_contours(stdlib::heightfield(rows, dx, dy, base, deg), smooth); });
}

const BuiltinEntry kShapeBuiltins[] = {
    {"pyramid",
     "pyramid(outline, apex)",
     pyramid_,
     "A pyramid over a planar outline of points with its tip at apex.",
     {&kPyramidParams}},
    {"tetrahedron",
     "tetrahedron(r: 1)",
     platonic_<stdlib::tetrahedron>,
     "The regular tetrahedron of circumradius r centred on the origin.",
     {&kPlatonicParams}},
    {"hexahedron",
     "hexahedron(r: 1)",
     platonic_<stdlib::hexahedron>,
     "The cube of circumradius r centred on the origin, axis-aligned.",
     {&kPlatonicParams}},
    {"octahedron",
     "octahedron(r: 1)",
     platonic_<stdlib::octahedron>,
     "The regular octahedron of circumradius r centred on the origin, corners on the axes.",
     {&kPlatonicParams}},
    {"dodecahedron",
     "dodecahedron(r: 1)",
     platonic_<stdlib::dodecahedron>,
     "The regular dodecahedron of circumradius r centred on the origin.",
     {&kPlatonicParams}},
    {"icosahedron",
     "icosahedron(r: 1)",
     platonic_<stdlib::icosahedron>,
     "The regular icosahedron of circumradius r centred on the origin.",
     {&kPlatonicParams}},
    {"cone",
     "cone(r, h, top: 0, sides: 32, crease: 30, contours: \"edges\")",
     cone_,
     "A cone of base radius r and height h on the origin, or a frustum when the top radius is not 0.",
     {&kConeParams}},
    {"extrude",
     "extrude(outline, v, holes: [])",
     extrude_,
     "A planar outline of points, with optional holes, swept along the vector v.",
     {&kExtrudeParams}},
    {"revolve",
     "revolve(profile, segments: 32, angle: 360, crease: 30, contours: \"edges\")",
     revolve_,
     "A profile of (r, 0, z) points turned about the z axis by angle degrees in segments steps.",
     {&kRevolveParams}},
    {"sweep",
     "sweep(profile, path, crease: 30, contours: \"edges\")",
     sweep_,
     "An xy-plane profile swept along a polyline path with mitred joints.",
     {&kSweepParams}},
    {"heightfield",
     "heightfield(values, dx: 1, dy: 1, base: none, crease: 30, contours: \"edges\")",
     heightfield_,
     "A terrain from rows of heights on a dx by dy grid: a surface, or a closed block down to base.",
     {&kHeightfieldParams}},
};

}  // namespace

void register_shape_builtins(BuiltinTable& table) { table.add_all(kShapeBuiltins); }

}  // namespace hlr::runtime
