// A fast path of the parser: an expression read by hand, by precedence climbing, to the very nodes the
// grammar's precedence cascade builds (grammar.hpp, plain_expression says when it runs and why).
#pragma once

#include <cstddef>

#include "lang/ast.hpp"

namespace hlr::lang {

// Reads the expression that starts at `at` (the text runs to `end`; `base` is the start of file `file`,
// for the spans) into `out` and returns the length of its text — or returns 0 when the grammar must read
// it: a form this reader leaves to the grammar (string interpolation), a mistake (the grammar reports
// it), or brackets and prefix operators nested so deep, with `nesting` levels already open around it,
// that the grammar's limit is near.
std::size_t read_plain_expression(const char* base, const char* at, const char* end, FileId file,
                                  std::size_t nesting, Expr& out);

}  // namespace hlr::lang
