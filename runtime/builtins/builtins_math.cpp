// math: trigonometry in degrees, powers and roots, rounding, min/max/clamp, interpolation, pi.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/format_number.hpp"
#include "runtime/builtins/angles.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kNumberOrVector = kinds(ValueKind::Number, ValueKind::Vector);

// f(x) for a one-number built-in; every instance binds this one list.
const ParamList kUnaryParams = {required("x", kNumber)};

template <double (*F)(double)>
Value unary(CallArgs& call) {
  const Bound b = call.bind(kUnaryParams);
  return finite_number(call, F(b.number(0)));
}

double asin_deg(double x) { return rad_to_deg(std::asin(x)); }
double acos_deg(double x) { return rad_to_deg(std::acos(x)); }
double atan_deg(double x) { return rad_to_deg(std::atan(x)); }
double sqrt_(double x) { return std::sqrt(x); }
double exp_(double x) { return std::exp(x); }
double log_(double x) { return x == 0 ? -HUGE_VAL : std::log(x); }
double abs_(double x) { return std::fabs(x); }
double floor_(double x) { return std::floor(x); }
double ceil_(double x) { return std::ceil(x); }
double round_(double x) { return std::round(x); }  // halves away from zero

const ParamList kAtan2Params = {required("y", kNumber), required("x", kNumber)};

Value atan2_(CallArgs& call) {
  const Bound b = call.bind(kAtan2Params);
  return finite_number(call, rad_to_deg(std::atan2(b.number(0), b.number(1))));
}

const ParamList kPowParams = {required("x", kNumber), required("y", kNumber)};

Value pow_(CallArgs& call) {
  const Bound b = call.bind(kPowParams);
  return finite_number(call, std::pow(b.number(0), b.number(1)));
}

// min(list) and max(list). Not a form of theirs: they take any count of numbers, which no list describes.
const ParamList kMinMaxListParams = {required("list", kinds(ValueKind::List))};

// min(a, b, ...) or min(list): the numbers compared.
std::vector<double> extremum_operands(CallArgs& call) {
  std::vector<double> xs;
  for (const Arg& a : call.args())
    if (!a.label.empty()) call.fail(a.label_span, call.site().function + "() takes no named arguments");
  if (call.args().size() == 1 && call.args()[0].value.is_sequence()) {
    xs = call.bind(kMinMaxListParams).numbers(0);
    if (xs.empty()) call.fail(call.args()[0].span, call.site().function + "() of an empty list");
    return xs;
  }
  if (call.args().empty()) call.fail_call(call.site().function + "() needs at least one number");
  for (const Arg& a : call.args()) {
    if (!a.value.is(ValueKind::Number))
      call.fail(a.span, "bad argument to " + call.site().function + "(): expected a number, got " +
                            kind_with_article(a.value.kind()));
    xs.push_back(a.value.as_number());
  }
  return xs;
}

Value min_(CallArgs& call) {
  const std::vector<double> xs = extremum_operands(call);
  return Value::number(*std::min_element(xs.begin(), xs.end()));
}

Value max_(CallArgs& call) {
  const std::vector<double> xs = extremum_operands(call);
  return Value::number(*std::max_element(xs.begin(), xs.end()));
}

const ParamList kClampParams = {required("x", kNumber), required("lo", kNumber), required("hi", kNumber)};

Value clamp_(CallArgs& call) {
  const Bound b = call.bind(kClampParams);
  if (b.number(1) > b.number(2))
    b.fail(2, "must not be below lo (" + format_for_message(b.number(1)) + "), got " +
                  format_for_message(b.number(2)));
  return Value::number(std::clamp(b.number(0), b.number(1), b.number(2)));
}

const ParamList kLerpParams = {required("a", kNumberOrVector), required("b", kNumberOrVector),
                               required("t", kNumber)};

// lerp(a, b, t) = a + (b − a)·t, for numbers or vectors.
Value lerp_(CallArgs& call) {
  const Bound b = call.bind(kLerpParams);
  const double t = b.number(2);
  if (b.value(0).kind() != b.value(1).kind())
    b.fail(1, "expected " + kind_with_article(b.value(0).kind()) + " like 'a', got " +
                  kind_with_article(b.value(1).kind()));
  if (b.value(0).is(ValueKind::Number))
    return finite_number(call, b.number(0) + (b.number(1) - b.number(0)) * t);
  return finite_vector(call, b.vector(0) + (b.vector(1) - b.vector(0)) * t);
}

const ParamList kSmoothstepParams = {required("e0", kNumber), required("e1", kNumber),
                                     required("x", kNumber)};

Value smoothstep_(CallArgs& call) {
  const Bound b = call.bind(kSmoothstepParams);
  if (b.number(0) == b.number(1))
    b.fail(1, "must differ from e0 (both are " + format_for_message(b.number(0)) + ")");
  const double t = std::clamp((b.number(2) - b.number(0)) / (b.number(1) - b.number(0)), 0.0, 1.0);
  return finite_number(call, t * t * (3 - 2 * t));
}

const BuiltinEntry kMathBuiltins[] = {
    {"sin", "sin(x)  (x in degrees)", unary<sin_deg>, "The sine of an angle in degrees.", {&kUnaryParams}},
    {"cos", "cos(x)  (x in degrees)", unary<cos_deg>, "The cosine of an angle in degrees.", {&kUnaryParams}},
    {"tan", "tan(x)  (x in degrees)", unary<tan_deg>, "The tangent of an angle in degrees.", {&kUnaryParams}},
    {"asin",
     "asin(x)  (result in degrees)",
     unary<asin_deg>,
     "The angle in degrees whose sine is x.",
     {&kUnaryParams}},
    {"acos",
     "acos(x)  (result in degrees)",
     unary<acos_deg>,
     "The angle in degrees whose cosine is x.",
     {&kUnaryParams}},
    {"atan",
     "atan(x)  (result in degrees)",
     unary<atan_deg>,
     "The angle in degrees whose tangent is x.",
     {&kUnaryParams}},
    {"atan2",
     "atan2(y, x)  (result in degrees)",
     atan2_,
     "The angle in degrees of the point (x, y) from the x axis, from -180 to 180.",
     {&kAtan2Params}},
    {"sqrt", "sqrt(x)", unary<sqrt_>, "The square root of x.", {&kUnaryParams}},
    {"pow", "pow(x, y)", pow_, "x raised to the power y.", {&kPowParams}},
    {"exp", "exp(x)", unary<exp_>, "e raised to the power x.", {&kUnaryParams}},
    {"log", "log(x)  (natural logarithm)", unary<log_>, "The natural logarithm of x.", {&kUnaryParams}},
    {"abs", "abs(x)", unary<abs_>, "The absolute value of x.", {&kUnaryParams}},
    {"floor", "floor(x)", unary<floor_>, "The largest whole number not above x.", {&kUnaryParams}},
    {"ceil", "ceil(x)", unary<ceil_>, "The smallest whole number not below x.", {&kUnaryParams}},
    {"round",
     "round(x)",
     unary<round_>,
     "x rounded to the nearest whole number, halves away from zero.",
     {&kUnaryParams}},
    {"min",
     "min(a, b, ...) | min(list)",
     min_,
     "The smallest of the numbers given, or of a list's numbers.",
     {}},
    {"max",
     "max(a, b, ...) | max(list)",
     max_,
     "The largest of the numbers given, or of a list's numbers.",
     {}},
    {"clamp", "clamp(x, lo, hi)", clamp_, "x limited to the range from lo to hi.", {&kClampParams}},
    {"lerp",
     "lerp(a, b, t)  (numbers or vectors)",
     lerp_,
     "The linear interpolation a + (b - a) * t, of numbers or of vectors.",
     {&kLerpParams}},
    {"smoothstep",
     "smoothstep(e0, e1, x)",
     smoothstep_,
     "A smooth step from 0 at x = e0 to 1 at x = e1 (Hermite 3t^2 - 2t^3), clamped outside.",
     {&kSmoothstepParams}},
};

}  // namespace

void register_math_builtins(BuiltinTable& table) {
  table.add_all(kMathBuiltins);
  table.add_constant("pi", Value::number(std::numbers::pi));
}

}  // namespace hlr::runtime
