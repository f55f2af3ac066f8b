// Expressions: literals, names, strings with interpolation, operators, member and index access.
#include <cmath>

#include "core/format_number.hpp"
#include "lang/overloaded.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/values/format_value.hpp"
#include "runtime/values/operators.hpp"

namespace hlr::runtime {

namespace {

using lang::Overloaded;

// An index value as a position in a sequence of `size` items; negative counts from the end.
std::size_t checked_index(const Value& index, std::size_t size, const lang::SourceSpan& span) {
  if (!index.is(ValueKind::Number))
    fail(span, "an index must be a number, got " + kind_with_article(index.kind()));
  const double i = index.as_number();
  if (std::floor(i) != i) fail(span, "an index must be a whole number, got " + format_for_message(i));
  const double n = static_cast<double>(size);
  if (i >= n || i < -n)
    fail(span,
         "index " + format_for_message(i) + " is out of range for " + std::to_string(size) +
             (size == 1 ? " item" : " items"),
         size == 0 ? "the list is empty"
                   : "valid indices are 0 to " + std::to_string(size - 1) + ", or -1 to -" +
                         std::to_string(size) + " from the end");
  return static_cast<std::size_t>(i < 0 ? i + n : i);
}

}  // namespace

Value Evaluator::eval(const lang::Expr& expr, const ScopePtr& scope) {
  const DepthGuard guard(eval_depth_, expr.span);
  budget_.step(expr.span);
  return std::visit(
      Overloaded{
          [&](const lang::NumberLit& n) {
            if (!std::isfinite(n.value))
              fail(expr.span, "this number is beyond the largest number (about 1.8e308)");
            return Value::number(n.value);
          },
          [&](const lang::BoolLit& b) { return Value::boolean(b.value); },
          [&](const lang::StringLit& s) { return eval_string(s, scope); },
          [&](const lang::VectorLit& v) {
            double xyz[3];
            static const char* const kAxis[] = {"x", "y", "z"};
            for (int i = 0; i < 3; ++i) {
              const Value c = eval(*v.components[i], scope);
              if (!c.is(ValueKind::Number))
                fail(v.components[i]->span, std::string("a vector's components must be numbers; ") +
                                                kAxis[i] + " is " + kind_with_article(c.kind()));
              xyz[i] = c.as_number();
            }
            return Value::vector({xyz[0], xyz[1], xyz[2]});
          },
          [&](const lang::ListLit& l) {
            List items;
            items.reserve(l.items.size());
            for (const auto& item : l.items) items.push_back(eval(*item, scope));
            return Value::list(std::move(items));
          },
          [&](const lang::ListComprehension& c) { return eval_comprehension(c, expr, scope); },
          [&](const lang::NameRef& n) { return eval_name(n, expr, scope); },
          [&](const lang::UnaryExpr& u) { return unary_op(u, eval(*u.operand, scope), expr.span); },
          [&](const lang::BinaryExpr& b) { return eval_binary(b, expr, scope); },
          [&](const lang::CallExpr& c) { return eval_call(c, expr, scope); },
          [&](const lang::MemberExpr& m) { return eval_member(m, scope); },
          [&](const lang::IndexExpr& i) { return eval_index(i, scope); },
      },
      expr.node);
}

Value Evaluator::eval_comprehension(const lang::ListComprehension& comp, const lang::Expr& expr,
                                    const ScopePtr& scope) {
  const Value items = eval(*comp.iterable, scope);
  if (!items.is_sequence())
    fail(comp.iterable->span,
         "a list comprehension needs a list or a range to walk, got " + kind_with_article(items.kind()),
         "for example: [i * i for i in 0..10] or [p.x for p in [(0, 0, 0), (1, 0, 0)]]");
  const std::size_t n = sequence_size(items);
  List out;
  for (std::size_t i = 0; i < n; ++i) {
    budget_.step(expr.span);
    auto item_scope = std::make_shared<Scope>(scope);  // one scope per item: closures keep their own item
    item_scope->define(comp.variable->text, sequence_item(items, i), comp.variable->span);
    if (comp.condition) {
      const Value keep = eval(*comp.condition, item_scope);
      if (!keep.is(ValueKind::Bool))
        fail(comp.condition->span,
             "a list comprehension's 'if' needs a bool condition, got " + kind_with_article(keep.kind()),
             "compare explicitly, e.g. [i for i in l if i != 0]");
      if (!keep.as_bool()) continue;
    }
    budget_.check_list_size(expr.span, out.size() + 1);
    out.push_back(eval(*comp.element, item_scope));
  }
  return Value::list(std::move(out));
}

Value Evaluator::eval_name(const lang::NameRef& ref, const lang::Expr& expr, const ScopePtr& scope) {
  if (const Binding* b = scope->find(ref.name)) return b->value;
  if (const Value* v = builtins().find(ref.name)) return *v;
  std::vector<std::string> candidates = scope->visible_names();
  const std::vector<std::string> builtin_names = builtins().names();
  candidates.insert(candidates.end(), builtin_names.begin(), builtin_names.end());
  std::string hint = did_you_mean(ref.name, candidates);
  if (hint.empty()) hint = "define it first with 'let " + ref.name + " = ...' or 'def " + ref.name + "(...)'";
  fail(expr.span, "unknown name '" + ref.name + "'", hint);
}

Value Evaluator::eval_string(const lang::StringLit& lit, const ScopePtr& scope) {
  std::string text;
  for (const lang::StringPart& part : lit.parts) {
    if (!part.expr) {
      text += part.text;
    } else {
      const Value v = eval(*part.expr, scope);
      try {
        const std::size_t room = budget_.limits().string - std::min(text.size(), budget_.limits().string);
        text += part.format.empty() ? display(v, room) : format_value(v, part.format, room);
      } catch (const FormatError& e) {
        fail(part.span, e.what());
      }
    }
    budget_.check_string_size(part.span, text.size());
  }
  budget_.step(lit.parts.empty() ? lang::SourceSpan{} : lit.parts.front().span, text.size() / 64);
  return Value::string(std::move(text));
}

Value Evaluator::eval_binary(const lang::BinaryExpr& bin, const lang::Expr& expr, const ScopePtr& scope) {
  (void)expr;
  if (bin.op == lang::BinaryOp::And || bin.op == lang::BinaryOp::Or) {
    const char* op = lang::to_string(bin.op);
    const Value a = eval(*bin.lhs, scope);
    if (!a.is(ValueKind::Bool))
      fail(bin.lhs->span, std::string("'") + op + "' needs bools, got " + kind_with_article(a.kind()));
    if (a.as_bool() == (bin.op == lang::BinaryOp::Or)) return a;  // short-circuit
    const Value b = eval(*bin.rhs, scope);
    if (!b.is(ValueKind::Bool))
      fail(bin.rhs->span, std::string("'") + op + "' needs bools, got " + kind_with_article(b.kind()));
    return b;
  }
  const Value a = eval(*bin.lhs, scope);
  const Value b = eval(*bin.rhs, scope);
  return binary_op(bin, a, b, budget_);
}

Value Evaluator::eval_member(const lang::MemberExpr& member, const ScopePtr& scope) {
  const Value object = eval(*member.object, scope);
  const std::string& m = member.member->text;
  if (object.is(ValueKind::Vector)) {
    const Vector3 v = object.as_vector();
    if (m == "x") return Value::number(v.x);
    if (m == "y") return Value::number(v.y);
    if (m == "z") return Value::number(v.z);
    fail(member.member->span, "a vector has no member '" + m + "'", "use .x, .y or .z");
  }
  fail(member.member->span, kind_with_article(object.kind()) + " has no member '" + m + "'",
       "only vectors have members (.x, .y, .z)");
}

Value Evaluator::eval_index(const lang::IndexExpr& index, const ScopePtr& scope) {
  const Value object = eval(*index.object, scope);
  const Value i = eval(*index.index, scope);
  if (object.is_sequence())
    return sequence_item(object, checked_index(i, sequence_size(object), index.index->span));
  if (object.is(ValueKind::Vector))
    return Value::number(object.as_vector()[static_cast<int>(checked_index(i, 3, index.index->span))]);
  fail(index.object->span, "cannot index " + kind_with_article(object.kind()),
       "only lists and vectors have items");
}

}  // namespace hlr::runtime
