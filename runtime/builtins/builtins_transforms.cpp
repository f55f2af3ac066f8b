// Transforms (affine maps of 3-space): identity, translate, rotate, scale, mirror, matrix. Angles in
// degrees, right-handed; `about: p` applies the map about the point p instead of the origin.
// `A then B` (in the language) applies A first.
#include <cmath>

#include "core/format_number.hpp"
#include "runtime/builtins/angles.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);

// `linear` applied about `about`: move `about` to the origin, apply, move back.
Affine3 about_point(const Affine3& linear, Point3 about) {
  const Vector3 p = to_vector(about);
  return Affine3::translation(-p).then(linear).then(Affine3::translation(p));
}

// Rodrigues' rotation about a unit axis, with sin/cos exact at multiples of 90°.
Affine3 rotation_deg(Vector3 u, double deg) {
  const double c = cos_deg(deg), s = sin_deg(deg), k = 1 - c;
  return Affine3::from_rows({c + u.x * u.x * k, u.x * u.y * k - u.z * s, u.x * u.z * k + u.y * s},
                            {u.y * u.x * k + u.z * s, c + u.y * u.y * k, u.y * u.z * k - u.x * s},
                            {u.z * u.x * k - u.y * s, u.z * u.y * k + u.x * s, c + u.z * u.z * k});
}

Value checked(const CallArgs& call, const Affine3& a) {
  for (int r = 0; r < 3; ++r) {
    finite_vector(call, a.row(r));
  }
  finite_vector(call, a.t);
  return Value::transform(a);
}

const ParamList kIdentityParams = {};

Value identity_(CallArgs& call) {
  call.bind(kIdentityParams);
  return Value::transform(Affine3::identity());
}

const ParamList kTranslateXyzParams = {required("x", kNumber), required("y", kNumber),
                                       required("z", kNumber)};
const ParamList kTranslateVectorParams = {required("v", kVector)};

Value translate_(CallArgs& call) {
  if (call.args().size() == 1 && (call.args()[0].value.is(ValueKind::Vector) || call.has_label("v")))
    return checked(call, Affine3::translation(call.bind(kTranslateVectorParams).vector(0)));
  const Bound b = call.bind(kTranslateXyzParams);
  return checked(call, Affine3::translation({b.number(0), b.number(1), b.number(2)}));
}

// One list for every form: which of its parameters are given picks the form.
const ParamList kRotateParams = {optional("degrees", kNumber), optional("axis", kVector),
                                 optional("x", kNumber),       optional("y", kNumber),
                                 optional("z", kNumber),       optional("about", kVector, Value::vector({}))};

Value rotate_(CallArgs& call) {
  const Bound b = call.bind(kRotateParams);
  Affine3 r;
  if (b.present(0)) {
    if (!b.present(1))
      call.fail_call("rotate(degrees) needs an axis: rotate(30, axis: (0, 0, 1)), or rotate(z: 30)");
    for (std::size_t i = 2; i <= 4; ++i)
      if (b.present(i)) b.fail(i, "cannot be combined with an angle and an axis");
    if (b.vector(1) == Vector3{}) b.fail(1, "the zero vector is not an axis");
    r = rotation_deg(normalize(b.vector(1)), b.number(0));
  } else {
    if (b.present(1)) b.fail(1, "needs the angle as the first argument: rotate(30, axis: (0, 0, 1))");
    if (!b.present(2) && !b.present(3) && !b.present(4))
      call.fail_call("rotate() needs an angle: rotate(z: 30), or rotate(30, axis: (0, 0, 1))");
    // Several axes: about x first, then y, then z.
    if (b.present(2)) r = r.then(rotation_deg({1, 0, 0}, b.number(2)));
    if (b.present(3)) r = r.then(rotation_deg({0, 1, 0}, b.number(3)));
    if (b.present(4)) r = r.then(rotation_deg({0, 0, 1}, b.number(4)));
  }
  return checked(call, about_point(r, b.point(5)));
}

const ParamList kScaleParams = {required("sx", kNumber), optional("sy", kNumber), optional("sz", kNumber),
                                optional("about", kVector, Value::vector({}))};

Value scale_(CallArgs& call) {
  const Bound b = call.bind(kScaleParams);
  if (b.present(1) != b.present(2))
    call.fail_call("scale() takes one factor or three: scale(2) or scale(1, 2, 3)");
  const double sx = b.number(0);
  const double sy = b.present(1) ? b.number(1) : sx, sz = b.present(2) ? b.number(2) : sx;
  for (std::size_t i = 0; i < 3; ++i)
    if (b.present(i) && b.number(i) == 0) b.fail(i, "must not be 0: a zero scale flattens the solid");
  return checked(call, about_point(Affine3::scaling(sx, sy, sz), b.point(3)));
}

const ParamList kMirrorParams = {required("normal", kVector), optional("about", kVector, Value::vector({}))};

Value mirror_(CallArgs& call) {
  const Bound b = call.bind(kMirrorParams);
  if (b.vector(0) == Vector3{}) b.fail(0, "the zero vector is not a normal");
  const Vector3 n = normalize(b.vector(0));
  // Householder reflection I − 2·n·nᵀ.
  const Affine3 h = Affine3::from_rows({1 - 2 * n.x * n.x, -2 * n.x * n.y, -2 * n.x * n.z},
                                       {-2 * n.y * n.x, 1 - 2 * n.y * n.y, -2 * n.y * n.z},
                                       {-2 * n.z * n.x, -2 * n.z * n.y, 1 - 2 * n.z * n.z});
  return checked(call, about_point(h, b.point(1)));
}

const ParamList kMatrixParams = {required("rows", kinds(ValueKind::List))};

Value matrix_(CallArgs& call) {
  const Bound b = call.bind(kMatrixParams);
  const Value& rows = b.value(0);
  const std::string shape = "must be 3 rows of 4 numbers: [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]";
  if (sequence_size(rows) != 3) b.fail(0, shape);
  Affine3 a;
  for (std::size_t r = 0; r < 3; ++r) {
    const Value row = sequence_item(rows, r);
    if (!row.is_sequence() || sequence_size(row) != 4)
      b.fail(0, shape + "; row " + std::to_string(r) + " is not");
    double v[4];
    for (std::size_t c = 0; c < 4; ++c) {
      const Value item = sequence_item(row, c);
      if (!item.is(ValueKind::Number))
        b.fail(0, "row " + std::to_string(r) + " item " + std::to_string(c) + " is " +
                      kind_with_article(item.kind()) + ", expected a number");
      v[c] = item.as_number();
    }
    a.m[r] = {v[0], v[1], v[2]};
    (r == 0 ? a.t.x : r == 1 ? a.t.y : a.t.z) = v[3];
  }
  const double det = a.determinant();
  if (det == 0 || !std::isfinite(det)) b.fail(0, "is singular (determinant " + format_for_message(det) + ")");
  return checked(call, a);
}

const BuiltinEntry kTransformBuiltins[] = {
    {"identity", "identity()", identity_, "The transform that moves nothing.", {&kIdentityParams}},
    {"translate",
     "translate(x, y, z) | translate(v)",
     translate_,
     "A translation by three numbers or by a vector.",
     {&kTranslateXyzParams, &kTranslateVectorParams}},
    {"rotate",
     "rotate(x: degrees) | rotate(y: degrees) | rotate(z: degrees) | rotate(degrees, axis: v)  (each with "
     "about: p)",
     rotate_,
     "A right-handed rotation in degrees about the x, y and z axes (in that order) or about a given axis, "
     "through the origin or the point about.",
     {&kRotateParams}},
    {"scale",
     "scale(sx) | scale(sx, sy, sz)  (each with about: p)",
     scale_,
     "A scaling by one factor or by one per axis, about the origin or the point about.",
     {&kScaleParams}},
    {"mirror",
     "mirror(normal: v, about: p)",
     mirror_,
     "The reflection in the plane perpendicular to normal through the origin or the point about.",
     {&kMirrorParams}},
    {"matrix",
     "matrix(rows)  (rows: [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]])",
     matrix_,
     "The affine map given by three rows of four numbers: the linear part and the translation.",
     {&kMatrixParams}},
};

}  // namespace

void register_transform_builtins(BuiltinTable& table) { table.add_all(kTransformBuiltins); }

}  // namespace hlr::runtime
