// Vectors (vec, dot, cross, norm, normalize, distance) and 2-D outlines (regular, rect): lists of
// vectors with z = 0, counter-clockwise, for prism() and friends.
#include "runtime/builtins.hpp"
#include "runtime/limits.hpp"
#include "stdlib/generators.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);

Value vec_(CallArgs& call) {
  static const std::vector<Param> params = {required("x", kNumber), required("y", kNumber),
                                            required("z", kNumber)};
  const Bound b = call.bind(params);
  return Value::vector({b.number(0), b.number(1), b.number(2)});
}

const std::vector<Param>& two_vectors() {
  static const std::vector<Param> params = {required("a", kVector), required("b", kVector)};
  return params;
}

Value dot_(CallArgs& call) {
  const Bound b = call.bind(two_vectors());
  return finite_number(call, dot(b.vector(0), b.vector(1)));
}

Value cross_(CallArgs& call) {
  const Bound b = call.bind(two_vectors());
  return finite_vector(call, cross(b.vector(0), b.vector(1)));
}

Value distance_(CallArgs& call) {
  const Bound b = call.bind(two_vectors());
  return finite_number(call, length(b.vector(0) - b.vector(1)));
}

Value norm_(CallArgs& call) {
  static const std::vector<Param> params = {required("v", kVector)};
  return finite_number(call, length(call.bind(params).vector(0)));
}

Value normalize_(CallArgs& call) {
  static const std::vector<Param> params = {required("v", kVector)};
  const Bound b = call.bind(params);
  if (b.vector(0) == Vector3{}) b.fail(0, "the zero vector has no direction");
  return finite_vector(call, normalize(b.vector(0)));
}

Value outline(const std::vector<Point2>& points) {
  List items;
  items.reserve(points.size());
  for (const Point2& p : points) items.push_back(Value::vector({p.x, p.y, 0}));
  return Value::list(std::move(items));
}

Value regular_(CallArgs& call) {
  static const std::vector<Param> params = {required("n", kNumber), required("r", kNumber),
                                            optional("phase", kNumber, Value::number(0))};
  const Bound b = call.bind(params);
  const int n = b.whole(0, 3, static_cast<int>(kMaxListItems));
  const double r = b.positive(1);
  call.budget().step(call.site().span, static_cast<std::uint64_t>(n));
  return outline(stdlib::regular_polygon(n, r, {}, b.number(2)));
}

Value rect_(CallArgs& call) {
  static const std::vector<Param> params = {required("w", kNumber), required("h", kNumber)};
  const Bound b = call.bind(params);
  const double w = b.positive(0) / 2, h = b.positive(1) / 2;
  return outline({{-w, -h}, {w, -h}, {w, h}, {-w, h}});
}

const BuiltinEntry kVectorBuiltins[] = {
    {"vec", "vec(x, y, z)", vec_},
    {"dot", "dot(a, b)", dot_},
    {"cross", "cross(a, b)", cross_},
    {"norm", "norm(v)", norm_},
    {"normalize", "normalize(v)", normalize_},
    {"distance", "distance(a, b)", distance_},
    {"regular", "regular(n, r, phase: 0)", regular_},
    {"rect", "rect(w, h)", rect_},
};

}  // namespace

void register_vector_builtins(BuiltinTable& table) { table.add_all(kVectorBuiltins); }

}  // namespace hlr::runtime
