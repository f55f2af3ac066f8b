// Fuzz target: bytes → the parser → the diagnostics printer (or the AST dump). The parser must return an
// AST or at least one diagnostic whose span lies in the text; printing either must work.
#include <cstdlib>
#include <sstream>

#include "lang/parser.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = hlr::fuzz::as_text(data, size);
  const hlr::lang::ParseResult result = hlr::lang::parse(text, "fuzz.hls");
  if (!result.source || result.ok() == !result.diagnostics.empty()) std::abort();
  for (const hlr::lang::Diagnostic& d : result.diagnostics)
    if (d.span.begin > d.span.end || d.span.end > text.size()) std::abort();
  std::ostringstream out;
  hlr::lang::print(out, result.diagnostics, *result.source);
  if (result.ok()) out << hlr::lang::dump(*result.script);
  return 0;
}
