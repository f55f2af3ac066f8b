// The public entry point of lang/: text in, AST or diagnostics out.
//
//   auto result = hlr::lang::parse(text, "scene.hls");
//   if (!result.ok()) hlr::lang::print(std::cerr, result.diagnostics, *result.source);
//   else run(*result.script);
//
// After a syntax error the parser skips to the next statement (a statement keyword at the start of
// a line, outside the braces the error was in) and goes on, so one run reports several errors; it
// stops after kMaxErrors. A script with any error yields no AST: nothing half-parsed is run.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lang/ast.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source.hpp"

namespace hlr::lang {

inline constexpr std::size_t kMaxErrors = 20;

struct ParseResult {
  std::shared_ptr<const SourceFile> source;  // the text the spans point into
  std::optional<Script> script;              // set exactly when there is no error
  std::vector<Diagnostic> diagnostics;       // errors, in source order; empty on success
  bool ok() const { return script.has_value(); }
};

struct ParseOptions {
  // Read plain solid items by hand (plain_solid_item.hpp). Off, the grammar reads every item: the tests
  // compare the two.
  bool plain_solid_items = true;
  // Read expressions by hand where they allow it (plain_expression.hpp). Off, the grammar reads them all:
  // the tests compare the two.
  bool plain_expressions = true;
  // The largest script read, in bytes: spans hold 32-bit offsets (source.hpp). A larger script is
  // refused with a message rather than given wrong positions. Tests lower it.
  std::size_t max_bytes = kMaxSourceBytes;
};

// `file_id` tells included files apart in spans; the runtime numbers the files it reads.
ParseResult parse(std::string_view source, std::string file_name, FileId file_id = 0,
                  const ParseOptions& options = {});
// The same for a file already made (the runtime's, which moves a file's text in rather than copying it).
ParseResult parse(std::shared_ptr<const SourceFile> file, const ParseOptions& options = {});

// Checks on a parsed script that need no evaluation (syntax_checks.cpp): `return` outside a
// function, a positional argument after a named one, an argument named twice, parameters
// repeated or without a default after one with a default. Appends errors to `out`.
void check_syntax(const Script& script, std::vector<Diagnostic>& out);

}  // namespace hlr::lang
