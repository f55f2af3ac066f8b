// Solid generators: each returns a solid named after its function ("box"). The table at the end lists
// them; a new generator is one function here and one row there (the stdlib does the geometry, this file
// only checks arguments and charges the frame's face budget before building).
#include <cmath>
#include <string>

#include "core/format_number.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"
#include "stdlib/desens_models.hpp"
#include "stdlib/generators.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);
constexpr KindSet kList = kinds(ValueKind::List);
constexpr int kMaxCount = static_cast<int>(kMaxFaces);  // sides, slices, steps: the face limit bounds them

// An outline argument: a list of at least 3 vectors in the xy plane.
std::vector<Point2> outline_arg(const Bound& b, std::size_t i, const std::string& what = "") {
  const std::vector<Vector3> points = b.vectors(i);
  if (points.size() < 3) b.fail(i, what + "needs at least 3 points, got " + std::to_string(points.size()));
  std::vector<Point2> out;
  out.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (points[k].z != 0)
      b.fail(i, what + "point " + std::to_string(k) + " has z = " + format_for_message(points[k].z) +
                    "; outlines lie in the xy plane (z = 0)");
    out.push_back({points[k].x, points[k].y});
  }
  return out;
}

// The implementation picks the form by the names given: min/max, then size/center, else the sizes.
const ParamList kBoxSizesParams = {required("sx", kNumber), required("sy", kNumber), required("sz", kNumber)};
const ParamList kBoxMinMaxParams = {required("min", kVector), required("max", kVector)};
const ParamList kBoxSizeCenterParams = {required("size", kVector),
                                        optional("center", kVector, Value::vector({}))};

Value box_(CallArgs& call) {
  if (call.has_label("min") || call.has_label("max")) {
    const Bound b = call.bind(kBoxMinMaxParams);
    const Point3 lo = b.point(0), hi = b.point(1);
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) b.fail(1, "must exceed min on every axis");
    return generated_solid(call, 6, [&] { return stdlib::box(lo, hi); });
  }
  if (call.has_label("size") || call.has_label("center")) {
    const Bound b = call.bind(kBoxSizeCenterParams);
    const Vector3 half = b.vector(0) / 2;
    if (!(half.x > 0 && half.y > 0 && half.z > 0)) b.fail(0, "must be positive on every axis");
    const Point3 c = b.point(1);
    return generated_solid(call, 6, [&] { return stdlib::box(c - half, c + half); });
  }
  const Bound b = call.bind(kBoxSizesParams);
  const Point3 hi{b.positive(0), b.positive(1), b.positive(2)};
  return generated_solid(call, 6, [&] { return stdlib::box({0, 0, 0}, hi); });
}

const ParamList kCubeParams = {required("s", kNumber)};

Value cube_(CallArgs& call) {
  const Bound b = call.bind(kCubeParams);
  const double h = b.positive(0) / 2;
  return generated_solid(call, 6, [&] { return stdlib::box({-h, -h, -h}, {h, h, h}); });
}

const ParamList kPrismParams = {required("outline", kList), required("h", kNumber),
                                optional("holes", kList, Value::list({}))};

Value prism_(CallArgs& call) {
  const Bound b = call.bind(kPrismParams);
  const std::vector<Point2> outline = outline_arg(b, 0);
  const double h = b.positive(1);
  std::vector<std::vector<Point2>> holes;
  std::size_t faces = outline.size() + 2;
  for_each_sublist(call, b, 2, "holes", "hole", "an outline (a list of vectors)",
                   [&](const Bound& one, std::size_t k) {
                     holes.push_back(outline_arg(one, 0, "hole " + std::to_string(k) + ": "));
                     faces += holes.back().size();
                   });
  return generated_solid(call, faces, [&] { return stdlib::prism(outline, holes, 0, h); });
}

const ParamList kCylinderParams = {required("r", kNumber), required("h", kNumber),
                                   optional("sides", kNumber, Value::number(32)), crease_param(),
                                   contours_param()};

Value cylinder_(CallArgs& call) {
  const Bound b = call.bind(kCylinderParams);
  const double r = b.positive(0), h = b.positive(1);
  const int sides = b.whole(2, 3, kMaxCount);
  const double deg = crease_angle(b, 3);
  const bool smooth = smooth_contours(b, 4);
  return generated_solid(call, static_cast<std::size_t>(sides) + 2, [&] {
    return with_contours(stdlib::cylinder({0, 0, 0}, r, h, sides, deg), smooth);
  });
}

const ParamList kSphereParams = {required("r", kNumber), optional("slices", kNumber, Value::number(32)),
                                 optional("stacks", kNumber, Value::number(16)), crease_param(),
                                 contours_param()};

Value sphere_(CallArgs& call) {
  const Bound b = call.bind(kSphereParams);
  const double r = b.positive(0);
  const int slices = b.whole(1, 3, kMaxCount), stacks = b.whole(2, 2, kMaxCount);
  const double deg = crease_angle(b, 3);
  const bool smooth = smooth_contours(b, 4);
  return generated_solid(call, static_cast<std::size_t>(slices) * static_cast<std::size_t>(stacks), [&] {
    return with_contours(stdlib::sphere({0, 0, 0}, r, slices, stacks, deg), smooth);
  });
}

const ParamList kTorusParams = {required("R", kNumber),
                                required("r", kNumber),
                                optional("major", kNumber, Value::number(48)),
                                optional("minor", kNumber, Value::number(24)),
                                crease_param(),
                                contours_param()};

Value torus_(CallArgs& call) {
  const Bound b = call.bind(kTorusParams);
  const double big = b.positive(0), small = b.positive(1);
  if (!(small < big))
    b.fail(1, "must be below R (" + format_for_message(big) + "), got " + format_for_message(small));
  const int major = b.whole(2, 3, kMaxCount), minor = b.whole(3, 3, kMaxCount);
  const double deg = crease_angle(b, 4);
  const bool smooth = smooth_contours(b, 5);
  return generated_solid(call, static_cast<std::size_t>(major) * static_cast<std::size_t>(minor), [&] {
    return with_contours(stdlib::torus({0, 0, 0}, big, small, major, minor, deg), smooth);
  });
}

const ParamList kStairsParams = {required("steps", kNumber), required("width", kNumber),
                                 required("rise", kNumber), required("run", kNumber)};

Value stairs_(CallArgs& call) {
  const Bound b = call.bind(kStairsParams);
  const int steps = b.whole(0, 1, kMaxCount / 2);
  const double width = b.positive(1), rise = b.positive(2), run = b.positive(3);
  return generated_solid(call, 2 * static_cast<std::size_t>(steps) + 4,
                         [&] { return stdlib::stairs(steps, width, rise, run); });
}

const ParamList kLblockParams = {required("size", kVector), required("upright", kNumber),
                                 required("foot", kNumber)};

// lblock(size, upright, foot): the L-shaped prism of stdlib::l_block, corner at the origin.
Value lblock_(CallArgs& call) {
  const Bound b = call.bind(kLblockParams);
  const Vector3 size = b.vector(0);
  if (!(size.x > 0 && size.y > 0 && size.z > 0)) b.fail(0, "must be positive on every axis");
  const double upright = b.positive(1), foot = b.positive(2);
  if (!(upright < size.x)) b.fail(1, "must be below size.x (" + format_for_message(size.x) + ")");
  if (!(foot < size.z)) b.fail(2, "must be below size.z (" + format_for_message(size.z) + ")");
  return generated_solid(call, 8, [&] { return stdlib::l_block({0, 0, 0}, size, upright, foot); });
}

const ParamList kDesensCarrierParams = {};

// desens_carrier(): Desens' aircraft carrier of 1969 (stdlib/desens_models.hpp), the demo's model.
Value desens_carrier_(CallArgs& call) {
  (void)call.bind(kDesensCarrierParams);
  return generated_solid(call, 32, [] { return stdlib::desens_carrier(); });
}

// The registration table of the solid generators.
const BuiltinEntry kSolidBuiltins[] = {
    {"box",
     "box(sx, sy, sz) | box(min: p, max: q) | box(size: v, center: p)",
     box_,
     "A box: by its three side lengths from the origin, by two corners, or by size and centre.",
     {&kBoxSizesParams, &kBoxMinMaxParams, &kBoxSizeCenterParams}},
    {"cube", "cube(s)", cube_, "A cube of side s centred on the origin.", {&kCubeParams}},
    {"prism",
     "prism(outline, h, holes: [])",
     prism_,
     "An xy-plane outline, with optional holes, extruded from z = 0 up to height h.",
     {&kPrismParams}},
    {"cylinder",
     "cylinder(r, h, sides: 32, crease: 30, contours: \"edges\")",
     cylinder_,
     "A cylinder of radius r and height h standing on the origin, its side made of sides flat faces.",
     {&kCylinderParams}},
    {"sphere",
     "sphere(r, slices: 32, stacks: 16, crease: 30, contours: \"edges\")",
     sphere_,
     "A sphere of radius r centred on the origin, slices around z and stacks from pole to pole.",
     {&kSphereParams}},
    {"torus",
     "torus(R, r, major: 48, minor: 24, crease: 30, contours: \"edges\")",
     torus_,
     "A torus about the z axis: ring radius R, tube radius r, major and minor segments.",
     {&kTorusParams}},
    {"stairs",
     "stairs(steps, width, rise, run)",
     stairs_,
     "A flight of steps rising along x from the origin, each rise high and run deep, width wide in y.",
     {&kStairsParams}},
    {"lblock",
     "lblock(size, upright, foot)",
     lblock_,
     "An L-shaped block with its corner at the origin, given its overall size, upright width and foot "
     "height.",
     {&kLblockParams}},
    {"desens_carrier",
     "desens_carrier()",
     desens_carrier_,
     "Desens' aircraft carrier model of 1969, the demo's scene.",
     {&kDesensCarrierParams}},
};

}  // namespace

void register_solid_builtins(BuiltinTable& table) { table.add_all(kSolidBuiltins); }

}  // namespace hlr::runtime
