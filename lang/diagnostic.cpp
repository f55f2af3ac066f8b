#include "lang/diagnostic.hpp"

#include <algorithm>
#include <ostream>
#include <string_view>

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

// A line longer than this many code points is quoted in part, from a little before the caret: a
// generated script may put megabytes on one line.
constexpr std::size_t kQuotedColumns = 160;
constexpr std::size_t kColumnsBeforeCaret = 60;
constexpr std::string_view kEllipsis = "\u2026";

// The quoted source line and a caret line under `span`, gutter included.
std::string excerpt(const SourceFile& file, const SourceSpan& span) {
  const SourcePos begin = file.position(span.begin);
  const SourcePos end = file.position(span.end);
  const std::string_view line = file.line_text(begin.line);
  const std::size_t columns = count_code_points(line);
  // Columns of the line the caret and its underline cover: [begin.column, stop).
  std::size_t stop = begin.column + 1;
  if (end.line == begin.line && end.column > begin.column) {
    stop = end.column;
  } else if (end.line > begin.line) {
    stop = std::max<std::size_t>(columns + 1, begin.column + 1);
  }
  std::string quoted(line);
  std::size_t caret = begin.column;  // in `quoted`
  if (columns > kQuotedColumns) {
    const std::size_t first =
        std::min(begin.column > kColumnsBeforeCaret ? begin.column - kColumnsBeforeCaret : 1,
                 columns - kQuotedColumns + 1);
    const std::size_t last = first + kQuotedColumns - 1;
    const std::size_t from = byte_at_column(line, first);
    const std::size_t to = byte_at_column(line, last + 1);
    quoted = std::string(first > 1 ? kEllipsis : "") + std::string(line.substr(from, to - from)) +
             std::string(to < line.size() ? kEllipsis : "");
    caret = begin.column - first + 1 + (first > 1 ? 1 : 0);
    stop = std::max<std::size_t>(std::min(stop, last + 1), begin.column + 1);
  }
  const std::string number = std::to_string(begin.line);
  const std::string gutter(std::max<std::size_t>(number.size(), 4), ' ');
  std::string out = std::string(gutter.size() - number.size(), ' ') + number + " | " + quoted + "\n";
  out += gutter + " | ";
  // Blank out what precedes the caret, keeping tabs so the caret lines up; one space per code point.
  std::size_t column = 1;
  for (std::size_t i = 0; i < quoted.size() && column < caret; ++i) {
    if (is_continuation_byte(quoted[i])) continue;
    out += quoted[i] == '\t' ? '\t' : ' ';
    ++column;
  }
  while (column < caret) {  // caret past the end of the line
    out += ' ';
    ++column;
  }
  out += '^';
  out += std::string(stop - begin.column - 1, '~');
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
