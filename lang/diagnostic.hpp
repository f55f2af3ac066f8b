// A diagnostic is what went wrong and where: severity, span, message, optional hint and notes. The
// printer shows it the same way everywhere (CLI, REPL, tests):
//
//   scene.hls:3:12: error: expected '=' after the vertex id, as in 'vertex 1 = (0, 0, 0)'
//       3 |   vertex 1 (0, 0, 0)
//         |            ^
//   hint: ...
//
// Columns are 1-based code points; the caret line copies the source line's tabs so that it lines
// up in any terminal, and a span longer than one character is underlined with '~'.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "lang/source.hpp"

namespace hlr::lang {

enum class Severity { Error, Warning, Note };

const char* to_string(Severity severity);  // "error", "warning", "note"

struct DiagnosticNote {
  SourceSpan span;
  std::string message;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceSpan span;
  std::string message;                // what is wrong, in one sentence, without a trailing period
  std::string hint;                   // how to fix it; empty when the message says it all
  std::vector<DiagnosticNote> notes;  // related places, e.g. where an unclosed '{' opened
};

// "file:line:col" of a span's start.
std::string location(const SourceFile& file, const SourceSpan& span);

// The full text of one diagnostic (several lines, each ending in '\n'). Spans must refer to `file`.
std::string format(const Diagnostic& diagnostic, const SourceFile& file);

void print(std::ostream& out, const std::vector<Diagnostic>& diagnostics, const SourceFile& file);

bool has_errors(const std::vector<Diagnostic>& diagnostics);

}  // namespace hlr::lang
