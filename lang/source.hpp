// Source text and positions. A SourceFile owns one script's text and knows where its lines start;
// a SourceSpan names a stretch of it by file id and byte offsets. Lines and columns are 1-based;
// a column counts code points (UTF-8), so a tab is one column and 'é' is one column. A span holds
// offsets only (12 bytes, and the parser never looks up a line): the line and column are asked of the
// SourceFile when a message is written, which is rare.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::lang {

using FileId = std::uint32_t;

struct SourcePos {
  std::uint32_t line = 1;    // 1-based
  std::uint32_t column = 1;  // 1-based, in code points
  std::uint32_t offset = 0;  // byte offset into the file's text
  friend bool operator==(const SourcePos&, const SourcePos&) = default;
};

// The largest script text a span can address: offsets are 32-bit.
inline constexpr std::size_t kMaxSourceBytes = 0xFFFF'FFFFU;

// [begin, end): byte offsets; end is one past the last character of the construct.
struct SourceSpan {
  FileId file = 0;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  friend bool operator==(const SourceSpan&, const SourceSpan&) = default;
};

class SourceFile {
 public:
  SourceFile(FileId id, std::string name, std::string text);

  FileId id() const { return id_; }
  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }

  // Position of a byte offset (clamped to the text's size).
  SourcePos position(std::size_t offset) const;
  // The span [begin, end), clamped to the text (and `end` to no less than `begin`).
  SourceSpan span(std::size_t begin, std::size_t end) const {
    begin = std::min(begin, text_.size());
    return {id_, static_cast<std::uint32_t>(begin),
            static_cast<std::uint32_t>(std::clamp(end, begin, text_.size()))};
  }
  // Line `line` (1-based) without its line terminator; empty when out of range.
  std::string_view line_text(std::uint32_t line) const;
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(line_starts_.size()); }
  // Lines whose first byte is a letter: about the number of top-level statements, for a reservation.
  std::size_t lines_starting_with_letter() const;

 private:
  FileId id_;
  std::string name_;
  std::string text_;
  std::vector<std::size_t> line_starts_;
  std::vector<bool> line_is_ascii_;  // columns of ASCII lines are byte differences: O(1)
};

// Number of code points in a UTF-8 string (continuation bytes are not counted; invalid bytes count one).
std::size_t count_code_points(std::string_view text);
// A byte that continues a UTF-8 code point (not its first byte).
inline bool is_continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U; }
// Byte offset of the code point numbered `column` (1-based) in `text`; text.size() past its end.
std::size_t byte_at_column(std::string_view text, std::size_t column);

}  // namespace hlr::lang
