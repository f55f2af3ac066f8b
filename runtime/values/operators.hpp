// The operators on values (LANGUAGE_SPEC.md, "Values"): arithmetic on numbers and vectors, list and
// string concatenation, comparisons, ranges, `then` on transforms. `and`/`or` short-circuit and live in
// the evaluator. A result that is not finite is an error at the operator, never an inf or NaN value.
#pragma once

#include "lang/ast.hpp"
#include "runtime/values/budget.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

Value unary_op(const lang::UnaryExpr& expr, const Value& operand, const lang::SourceSpan& span);

// `bin` supplies the spans: the operator's for type errors, the divisor's for a division by zero.
Value binary_op(const lang::BinaryExpr& bin, const Value& lhs, const Value& rhs, Budget& budget);

}  // namespace hlr::runtime
