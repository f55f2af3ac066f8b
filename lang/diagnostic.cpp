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

// Byte offset of code point `column` (1-based) of `line`; line.size() past its end.
std::size_t byte_at_column(std::string_view line, std::size_t column) {
  std::size_t seen = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if ((static_cast<unsigned char>(line[i]) & 0xC0U) == 0x80U) continue;
    if (++seen == column) return i;
  }
  return line.size();
}

// The quoted source line and a caret line under `span`, gutter included.
std::string excerpt(const SourceFile& file, const SourceSpan& span) {
  const SourcePos begin = file.position(span.begin);
  const SourcePos end = file.position(span.end);
  std::string_view line = file.line_text(begin.line);
  const std::size_t columns = count_code_points(line);
  // Columns of the line the caret and its underline cover: [begin.column, stop).
  std::size_t stop = begin.column + 1;
  if (end.line == begin.line && end.column > begin.column) {
    stop = end.column;
  } else if (end.line > begin.line) {
    stop = std::max<std::size_t>(columns + 1, begin.column + 1);
  }
  std::size_t caret = begin.column;  // in the quoted text
  std::string_view before;
  std::string_view after;
  if (columns > kQuotedColumns) {
    const std::size_t first =
        std::min(begin.column > kColumnsBeforeCaret ? begin.column - kColumnsBeforeCaret : 1,
                 columns - kQuotedColumns + 1);
    const std::size_t last = first + kQuotedColumns - 1;
    const std::size_t from = byte_at_column(line, first);
    const std::size_t to = byte_at_column(line, last + 1);
    if (first > 1) before = kEllipsis;
    if (to < line.size()) after = kEllipsis;
    line = line.substr(from, to - from);
    caret = begin.column - first + 1 + (before.empty() ? 0 : 1);
    stop = std::max<std::size_t>(std::min(stop, last + 1), begin.column + 1);
  }
  const std::string number = std::to_string(begin.line);
  const std::string gutter(std::max<std::size_t>(number.size(), 4), ' ');
  std::string out = std::string(gutter.size() - number.size(), ' ') + number + " | " + std::string(before) +
                    std::string(line) + std::string(after) + "\n";
  out += gutter + " | ";
  // Blank out what precedes the caret, keeping tabs so the caret lines up; one space per code point.
  std::size_t column = 1;
  if (!before.empty()) {
    out += ' ';
    ++column;
  }
  for (std::size_t i = 0; i < line.size() && column < caret; ++i) {
    const auto byte = static_cast<unsigned char>(line[i]);
    if ((byte & 0xC0U) == 0x80U) continue;
    out += line[i] == '\t' ? '\t' : ' ';
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
