#include "runtime/values/operators.hpp"

#include <cmath>

#include "core/format_number.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

namespace {

using lang::BinaryOp;

[[noreturn]] void type_error(const lang::BinaryExpr& bin, const Value& a, const Value& b) {
  const std::string op = lang::to_string(bin.op);
  std::string hint;
  if (a.is(ValueKind::Vector) && b.is(ValueKind::Vector) &&
      (bin.op == BinaryOp::Mul || bin.op == BinaryOp::Div))
    hint = "vectors multiply with dot(a, b) or cross(a, b)";
  else if (a.is(ValueKind::String) || b.is(ValueKind::String))
    hint = "to put a value into text, interpolate it: \"width {w}\"";
  else if (a.is(ValueKind::Transform) && b.is(ValueKind::Transform))
    hint =
        "transforms compose with 'then', which applies the left one first: 'rotate(z: 30) then "
        "translate(1, 0, 0)'";
  else if (bin.op == BinaryOp::Then)
    hint = "'then' chains transforms: translate(1, 0, 0) then rotate(z: 30)";
  else if (a.is(ValueKind::Number) && b.is(ValueKind::Vector) && bin.op == BinaryOp::Div)
    hint = "a vector can be divided by a number, not the other way round";
  const bool compare = bin.op >= BinaryOp::Eq && bin.op <= BinaryOp::Ge;
  if (!compare && a.is(ValueKind::Transform) && b.is(ValueKind::Transform))
    fail(bin.op_span, "cannot apply '" + op + "' to two transforms: transforms compose with 'then'", hint);
  fail(bin.op_span,
       compare ? "cannot compare " + kind_with_article(a.kind()) + " with " + kind_with_article(b.kind()) +
                     " using '" + op + "'"
               : "cannot apply '" + op + "' to " + kind_with_article(a.kind()) + " and " +
                     kind_with_article(b.kind()),
       hint);
}

double finite(const lang::BinaryExpr& bin, double x, double a, double b) {
  if (!std::isfinite(x))
    fail(bin.op_span, "arithmetic overflow: " + format_for_message(a) + " " + lang::to_string(bin.op) + " " +
                          format_for_message(b) + " is beyond the largest number (about 1.8e308)");
  return x;
}

Vector3 finite(const lang::BinaryExpr& bin, Vector3 v) {
  if (!is_finite(to_point(v)))
    fail(bin.op_span, std::string("arithmetic overflow: the vector '") + lang::to_string(bin.op) +
                          "' gives a component beyond the largest number (about 1.8e308)");
  return v;
}

void check_divisor(const lang::BinaryExpr& bin, double divisor) {
  if (divisor == 0)
    fail(bin.rhs->span, bin.op == BinaryOp::Mod ? "modulo by zero" : "division by zero",
         "the divisor evaluates to 0");
}

Value arithmetic(const lang::BinaryExpr& bin, double a, double b) {
  switch (bin.op) {
    case BinaryOp::Add:
      return Value::number(finite(bin, a + b, a, b));
    case BinaryOp::Sub:
      return Value::number(finite(bin, a - b, a, b));
    case BinaryOp::Mul:
      return Value::number(finite(bin, a * b, a, b));
    case BinaryOp::Div:
      check_divisor(bin, b);
      return Value::number(finite(bin, a / b, a, b));
    case BinaryOp::Mod:
      check_divisor(bin, b);
      return Value::number(finite(bin, a - b * std::floor(a / b), a, b));  // floored: -1 % 3 == 2
    case BinaryOp::Lt:
      return Value::boolean(a < b);
    case BinaryOp::Le:
      return Value::boolean(a <= b);
    case BinaryOp::Gt:
      return Value::boolean(a > b);
    case BinaryOp::Ge:
      return Value::boolean(a >= b);
    default:
      return Value();
  }
}

Value concatenate(const lang::BinaryExpr& bin, const Value& a, const Value& b, Budget& budget) {
  const std::size_t n = sequence_size(a) + sequence_size(b);
  budget.check_list_size(bin.op_span, n);
  budget.step(bin.op_span, n / 8);  // copying is work: a loop of big concatenations must hit the step limit
  List items;
  items.reserve(n);
  for (const Value* v : {&a, &b})
    for (std::size_t i = 0; i < sequence_size(*v); ++i) items.push_back(sequence_item(*v, i));
  return Value::list(std::move(items));
}

Value make_range(const lang::BinaryExpr& bin, double a, double b, const Budget& budget) {
  const double count = std::ceil(b - a);
  const std::size_t limit = budget.limits().list;
  if (count > static_cast<double>(limit))
    fail(bin.op_span, limit_message("items in a list", limit, "list") + ": " + format_for_message(a) + ".." +
                          format_for_message(b) + " has " + format_for_message(count));
  return Value::range({a, 1, count > 0 ? static_cast<std::size_t>(count) : 0});
}

}  // namespace

Value unary_op(const lang::UnaryExpr& expr, const Value& v, const lang::SourceSpan& span) {
  if (expr.op == lang::UnaryOp::Not) {
    if (!v.is(ValueKind::Bool)) fail(span, "'not' needs a bool, got " + kind_with_article(v.kind()));
    return Value::boolean(!v.as_bool());
  }
  if (v.is(ValueKind::Number)) return Value::number(-v.as_number());
  if (v.is(ValueKind::Vector)) return Value::vector(-v.as_vector());
  fail(span, "cannot negate " + kind_with_article(v.kind()));
}

Value binary_op(const lang::BinaryExpr& bin, const Value& a, const Value& b, Budget& budget) {
  const ValueKind ka = a.kind(), kb = b.kind();
  const bool num = ka == ValueKind::Number && kb == ValueKind::Number;
  switch (bin.op) {
    case BinaryOp::Eq:
    case BinaryOp::Ne: {
      if (ka != kb && !(a.is_sequence() && b.is_sequence())) type_error(bin, a, b);
      budget.step(bin.op_span, a.is_sequence() ? sequence_size(a) / 8 : 0);
      return Value::boolean(values_equal(a, b) == (bin.op == BinaryOp::Eq));
    }
    case BinaryOp::Lt:
    case BinaryOp::Le:
    case BinaryOp::Gt:
    case BinaryOp::Ge:
      if (!num) type_error(bin, a, b);
      return arithmetic(bin, a.as_number(), b.as_number());
    case BinaryOp::Range:
      if (!num) type_error(bin, a, b);
      return make_range(bin, a.as_number(), b.as_number(), budget);
    case BinaryOp::Add:
    case BinaryOp::Sub:
      if (num) return arithmetic(bin, a.as_number(), b.as_number());
      if (ka == ValueKind::Vector && kb == ValueKind::Vector)
        return Value::vector(finite(
            bin, bin.op == BinaryOp::Add ? a.as_vector() + b.as_vector() : a.as_vector() - b.as_vector()));
      if (bin.op == BinaryOp::Add && a.is_sequence() && b.is_sequence())
        return concatenate(bin, a, b, budget);
      if (bin.op == BinaryOp::Add && ka == ValueKind::String && kb == ValueKind::String) {
        budget.check_string_size(bin.op_span, a.as_string().size() + b.as_string().size());
        budget.step(bin.op_span, (a.as_string().size() + b.as_string().size()) / 64);
        return Value::string(a.as_string() + b.as_string());
      }
      type_error(bin, a, b);
    case BinaryOp::Mul:
      if (num) return arithmetic(bin, a.as_number(), b.as_number());
      if (ka == ValueKind::Vector && kb == ValueKind::Number)
        return Value::vector(finite(bin, a.as_vector() * b.as_number()));
      if (ka == ValueKind::Number && kb == ValueKind::Vector)
        return Value::vector(finite(bin, a.as_number() * b.as_vector()));
      type_error(bin, a, b);
    case BinaryOp::Div:
      if (num) return arithmetic(bin, a.as_number(), b.as_number());
      if (ka == ValueKind::Vector && kb == ValueKind::Number) {
        check_divisor(bin, b.as_number());
        return Value::vector(finite(bin, a.as_vector() / b.as_number()));
      }
      type_error(bin, a, b);
    case BinaryOp::Mod:
      if (num) return arithmetic(bin, a.as_number(), b.as_number());
      type_error(bin, a, b);
    case BinaryOp::Then:
      if (ka == ValueKind::Transform && kb == ValueKind::Transform) {
        const Affine3 r = a.as_transform().then(b.as_transform());
        for (int i = 0; i < 3; ++i) finite(bin, r.row(i));
        finite(bin, r.t);
        return Value::transform(r);
      }
      type_error(bin, a, b);
    case BinaryOp::And:
    case BinaryOp::Or:
      break;  // short-circuit: the evaluator's
  }
  type_error(bin, a, b);
}

}  // namespace hlr::runtime
