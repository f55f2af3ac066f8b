// Internal to lang/: match one statement of a file and build its AST node (ast_builder.cpp).
// parser.cpp drives it statement by statement and turns SyntaxErrors into diagnostics.
#pragma once

#include <cstddef>
#include <optional>

#include "lang/ast.hpp"
#include "lang/parse_state.hpp"
#include "lang/source.hpp"

namespace hlr::lang::detail {

struct StatementParse {
  std::optional<Stmt> statement;     // set on success
  std::size_t end = 0;               // byte offset just past the statement
  std::optional<SyntaxError> error;  // set on failure
};

// Parses the statement that starts at `offset` (which must not be padding or the end of the text).
// `state` is the parser's working memory, reused from one statement to the next of a file so that its
// stacks keep their capacity; it is reset here.
StatementParse parse_statement(const SourceFile& file, std::size_t offset, ParseState& state);

}  // namespace hlr::lang::detail
