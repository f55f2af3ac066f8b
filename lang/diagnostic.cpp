#include "lang/diagnostic.hpp"

#include <algorithm>
#include <ostream>

namespace hlr::lang {

const char* to_string(Severity severity) {
  switch (severity) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

std::string location(const SourceFile& file, const SourceSpan& span) {
  const SourcePos begin = file.position(span.begin);
  return file.name() + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column);
}

namespace {

// The quoted source line and a caret line under `span`, gutter included.
std::string excerpt(const SourceFile& file, const SourceSpan& span) {
  const SourcePos begin = file.position(span.begin);
  const SourcePos end = file.position(span.end);
  const std::string_view line = file.line_text(begin.line);
  const std::string number = std::to_string(begin.line);
  const std::string gutter(std::max<std::size_t>(number.size(), 4), ' ');
  std::string out =
      std::string(gutter.size() - number.size(), ' ') + number + " | " + std::string(line) + "\n";
  out += gutter + " | ";
  // Blank out what precedes the caret, keeping tabs so the caret lines up; one space per code point.
  std::size_t column = 1;
  for (std::size_t i = 0; i < line.size() && column < begin.column; ++i) {
    const auto byte = static_cast<unsigned char>(line[i]);
    if ((byte & 0xC0U) == 0x80U) continue;
    out += line[i] == '\t' ? '\t' : ' ';
    ++column;
  }
  while (column < begin.column) {  // caret past the end of the line
    out += ' ';
    ++column;
  }
  out += '^';
  std::size_t width = 1;
  if (end.line == begin.line && end.column > begin.column) {
    width = end.column - begin.column;
  } else if (end.line > begin.line) {
    const std::size_t line_width = count_code_points(line) + 1;
    width = line_width > begin.column ? line_width - begin.column : 1;
  }
  out += std::string(width - 1, '~');
  return out + "\n";
}

}  // namespace

std::string format(const Diagnostic& diagnostic, const SourceFile& file) {
  std::string out = location(file, diagnostic.span) + ": " + to_string(diagnostic.severity) + ": " +
                    diagnostic.message + "\n";
  out += excerpt(file, diagnostic.span);
  if (!diagnostic.hint.empty()) out += "hint: " + diagnostic.hint + "\n";
  for (const auto& note : diagnostic.notes) {
    out += location(file, note.span) + ": note: " + note.message + "\n";
    out += excerpt(file, note.span);
  }
  return out;
}

void print(std::ostream& out, const std::vector<Diagnostic>& diagnostics, const SourceFile& file) {
  for (const auto& diagnostic : diagnostics) out << format(diagnostic, file);
}

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

}  // namespace hlr::lang
