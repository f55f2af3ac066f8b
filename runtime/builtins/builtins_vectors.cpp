// Vectors (vec, dot, cross, norm, normalize, distance) and 2-D outlines (regular, rect): lists of
// vectors with z = 0, counter-clockwise, for prism() and friends.
#include "runtime/base/limits.hpp"
#include "runtime/builtins/builtins.hpp"
#include "stdlib/generators.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);

const ParamList kVecParams = {required("x", kNumber), required("y", kNumber), required("z", kNumber)};

Value vec_(CallArgs& call) {
  const Bound b = call.bind(kVecParams);
  return Value::vector({b.number(0), b.number(1), b.number(2)});
}

// dot, cross and distance.
const ParamList kTwoVectorParams = {required("a", kVector), required("b", kVector)};

Value dot_(CallArgs& call) {
  const Bound b = call.bind(kTwoVectorParams);
  return finite_number(call, dot(b.vector(0), b.vector(1)));
}

Value cross_(CallArgs& call) {
  const Bound b = call.bind(kTwoVectorParams);
  return finite_vector(call, cross(b.vector(0), b.vector(1)));
}

Value distance_(CallArgs& call) {
  const Bound b = call.bind(kTwoVectorParams);
  return finite_number(call, length(b.vector(0) - b.vector(1)));
}

const ParamList kNormParams = {required("v", kVector)};

Value norm_(CallArgs& call) { return finite_number(call, length(call.bind(kNormParams).vector(0))); }

const ParamList kNormalizeParams = {required("v", kVector)};

Value normalize_(CallArgs& call) {
  const Bound b = call.bind(kNormalizeParams);
  if (b.vector(0) == Vector3{}) b.fail(0, "the zero vector has no direction");
  return finite_vector(call, normalize(b.vector(0)));
}

Value outline(const std::vector<Point2>& points) {
  List items;
  items.reserve(points.size());
  for (const Point2& p : points) items.push_back(Value::vector({p.x, p.y, 0}));
  return Value::list(std::move(items));
}

const ParamList kRegularParams = {required("n", kNumber), required("r", kNumber),
                                  optional("phase", kNumber, Value::number(0))};

Value regular_(CallArgs& call) {
  const Bound b = call.bind(kRegularParams);
  const int n = b.whole(0, 3, static_cast<int>(kMaxListItems));
  const double r = b.positive(1);
  call.budget().step(call.site().span, static_cast<std::uint64_t>(n));
  return outline(stdlib::regular_polygon(n, r, {}, b.number(2)));
}

const ParamList kRectParams = {required("w", kNumber), required("h", kNumber)};

Value rect_(CallArgs& call) {
  const Bound b = call.bind(kRectParams);
  const double w = b.positive(0) / 2, h = b.positive(1) / 2;
  return outline({{-w, -h}, {w, -h}, {w, h}, {-w, h}});
}

const BuiltinEntry kVectorBuiltins[] = {
    {"vec", "vec(x, y, z)", vec_, "The vector (x, y, z) from three numbers.", {&kVecParams}},
    {"dot", "dot(a, b)", dot_, "The dot product of two vectors.", {&kTwoVectorParams}},
    {"cross",
     "cross(a, b)",
     cross_,
     "The cross product of two vectors, a right-handed normal to both.",
     {&kTwoVectorParams}},
    {"norm", "norm(v)", norm_, "The length of a vector.", {&kNormParams}},
    {"normalize", "normalize(v)", normalize_, "A non-zero vector scaled to length 1.", {&kNormalizeParams}},
    {"distance", "distance(a, b)", distance_, "The distance between two points.", {&kTwoVectorParams}},
    {"regular",
     "regular(n, r, phase: 0)",
     regular_,
     "The outline of a regular n-gon of circumradius r about the origin, its first corner at phase degrees.",
     {&kRegularParams}},
    {"rect",
     "rect(w, h)",
     rect_,
     "The outline of a w by h rectangle centred on the origin in the xy plane.",
     {&kRectParams}},
};

}  // namespace

void register_vector_builtins(BuiltinTable& table) { table.add_all(kVectorBuiltins); }

}  // namespace hlr::runtime
