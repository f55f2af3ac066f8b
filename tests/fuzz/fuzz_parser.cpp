// Fuzz target: bytes → the parser → the diagnostics printer (or the AST dump). The parser must return an
// AST or at least one diagnostic whose span lies in the text; printing either must work. The hand readers
// (plain expressions, plain solid items) are shortcuts only: the grammar alone must print the same.
#include <cstdlib>
#include <sstream>
#include <string>

#include "lang/parser.hpp"
#include "tests/fuzz/fuzz_input.hpp"

namespace {

std::string printed(const hlr::lang::ParseResult& result) {
  std::ostringstream out;
  hlr::lang::print(out, result.diagnostics, *result.source);
  if (result.ok()) out << hlr::lang::dump(*result.script);
  return out.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = hlr::fuzz::as_text(data, size);
  const hlr::lang::ParseResult result = hlr::lang::parse(text, "fuzz.hls");
  if (!result.source || result.ok() == !result.diagnostics.empty()) std::abort();
  for (const hlr::lang::Diagnostic& d : result.diagnostics)
    if (d.span.begin > d.span.end || d.span.end > text.size()) std::abort();
  hlr::lang::ParseOptions grammar_only;
  grammar_only.plain_solid_items = false;
  grammar_only.plain_expressions = false;
  if (printed(result) != printed(hlr::lang::parse(text, "fuzz.hls", 0, grammar_only))) std::abort();
  return 0;
}
