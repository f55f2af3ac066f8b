// math: trigonometry in degrees, powers and roots, rounding, min/max/clamp, interpolation, pi.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/format_number.hpp"
#include "runtime/angles.hpp"
#include "runtime/builtins.hpp"
#include "runtime/format_value.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kNumberOrVector = kinds(ValueKind::Number, ValueKind::Vector);

// f(x) for a one-number built-in.
template <double (*F)(double)>
Value unary(CallArgs& call) {
  static const std::vector<Param> params = {required("x", kNumber)};
  const Bound b = call.bind(params);
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

Value atan2_(CallArgs& call) {
  static const std::vector<Param> params = {required("y", kNumber), required("x", kNumber)};
  const Bound b = call.bind(params);
  return finite_number(call, rad_to_deg(std::atan2(b.number(0), b.number(1))));
}

Value pow_(CallArgs& call) {
  static const std::vector<Param> params = {required("x", kNumber), required("y", kNumber)};
  const Bound b = call.bind(params);
  return finite_number(call, std::pow(b.number(0), b.number(1)));
}

// min(a, b, ...) or min(list): the numbers compared.
std::vector<double> extremum_operands(CallArgs& call) {
  std::vector<double> xs;
  for (const Arg& a : call.args())
    if (!a.label.empty()) call.fail(a.label_span, call.site().function + "() takes no named arguments");
  if (call.args().size() == 1 && call.args()[0].value.is_sequence()) {
    static const std::vector<Param> params = {required("list", kinds(ValueKind::List))};
    xs = call.bind(params).numbers(0);
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

Value clamp_(CallArgs& call) {
  static const std::vector<Param> params = {required("x", kNumber), required("lo", kNumber),
                                            required("hi", kNumber)};
  const Bound b = call.bind(params);
  if (b.number(1) > b.number(2))
    b.fail(2, "must not be below lo (" + format_for_message(b.number(1)) + "), got " +
                  format_for_message(b.number(2)));
  return Value::number(std::clamp(b.number(0), b.number(1), b.number(2)));
}

// lerp(a, b, t) = a + (b − a)·t, for numbers or vectors.
Value lerp_(CallArgs& call) {
  static const std::vector<Param> params = {required("a", kNumberOrVector), required("b", kNumberOrVector),
                                            required("t", kNumber)};
  const Bound b = call.bind(params);
  const double t = b.number(2);
  if (b.value(0).kind() != b.value(1).kind())
    b.fail(1, "expected " + kind_with_article(b.value(0).kind()) + " like 'a', got " +
                  kind_with_article(b.value(1).kind()));
  if (b.value(0).is(ValueKind::Number))
    return finite_number(call, b.number(0) + (b.number(1) - b.number(0)) * t);
  return finite_vector(call, b.vector(0) + (b.vector(1) - b.vector(0)) * t);
}

Value smoothstep_(CallArgs& call) {
  static const std::vector<Param> params = {required("e0", kNumber), required("e1", kNumber),
                                            required("x", kNumber)};
  const Bound b = call.bind(params);
  if (b.number(0) == b.number(1))
    b.fail(1, "must differ from e0 (both are " + format_for_message(b.number(0)) + ")");
  const double t = std::clamp((b.number(2) - b.number(0)) / (b.number(1) - b.number(0)), 0.0, 1.0);
  return finite_number(call, t * t * (3 - 2 * t));
}

const BuiltinEntry kMathBuiltins[] = {
    {"sin", "sin(degrees)", unary<sin_deg>},
    {"cos", "cos(degrees)", unary<cos_deg>},
    {"tan", "tan(degrees)", unary<tan_deg>},
    {"asin", "asin(x)  (result in degrees)", unary<asin_deg>},
    {"acos", "acos(x)  (result in degrees)", unary<acos_deg>},
    {"atan", "atan(x)  (result in degrees)", unary<atan_deg>},
    {"atan2", "atan2(y, x)  (result in degrees)", atan2_},
    {"sqrt", "sqrt(x)", unary<sqrt_>},
    {"pow", "pow(x, y)", pow_},
    {"exp", "exp(x)", unary<exp_>},
    {"log", "log(x)  (natural logarithm)", unary<log_>},
    {"abs", "abs(x)", unary<abs_>},
    {"floor", "floor(x)", unary<floor_>},
    {"ceil", "ceil(x)", unary<ceil_>},
    {"round", "round(x)", unary<round_>},
    {"min", "min(a, b, ...) | min(list)", min_},
    {"max", "max(a, b, ...) | max(list)", max_},
    {"clamp", "clamp(x, lo, hi)", clamp_},
    {"lerp", "lerp(a, b, t)  (numbers or vectors)", lerp_},
    {"smoothstep", "smoothstep(e0, e1, x)", smoothstep_},
};

}  // namespace

void register_math_builtins(BuiltinTable& table) {
  table.add_all(kMathBuiltins);
  table.add_constant("pi", Value::number(std::numbers::pi));
}

}  // namespace hlr::runtime
