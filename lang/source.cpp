#include "lang/source.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace hlr::lang {

SourceFile::SourceFile(FileId id, std::string name, std::string text)
    : id_(id), name_(std::move(name)), text_(std::move(text)) {
  // A UTF-8 byte-order mark, which some editors write first, is not part of the script: dropped, so that
  // it is neither an unexpected character nor a column.
  if (text_.starts_with("\xEF\xBB\xBF")) text_.erase(0, 3);
  // Counted first, so the tables are allocated once (a generated script has millions of lines); then
  // each line is found by memchr and checked for non-ASCII bytes in one branch-free pass.
  const std::size_t lines = 1 + static_cast<std::size_t>(std::count(text_.begin(), text_.end(), '\n'));
  line_starts_.reserve(lines);
  line_is_ascii_.reserve(lines);
  const char* const data = text_.data();
  std::size_t begin = 0;
  for (;;) {
    const void* newline = std::memchr(data + begin, '\n', text_.size() - begin);
    const std::size_t end =
        newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - data) : text_.size();
    unsigned char bits = 0;
    for (std::size_t i = begin; i < end; ++i) bits |= static_cast<unsigned char>(data[i]);
    line_starts_.push_back(begin);
    line_is_ascii_.push_back(bits < 0x80U);
    if (!newline) break;
    begin = end + 1;
  }
}

std::size_t SourceFile::lines_starting_with_letter() const {
  std::size_t n = 0;
  for (const std::size_t start : line_starts_)
    if (start < text_.size() && std::isalpha(static_cast<unsigned char>(text_[start]))) ++n;
  return n;
}

std::size_t count_code_points(std::string_view text) {
  std::size_t n = 0;
  for (const char c : text) {
    if (!is_continuation_byte(c)) ++n;
  }
  return n;
}

std::size_t byte_at_column(std::string_view text, std::size_t column) {
  std::size_t seen = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!is_continuation_byte(text[i]) && ++seen == column) return i;
  }
  return text.size();
}

SourcePos SourceFile::position(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line_index = static_cast<std::size_t>(it - line_starts_.begin()) - 1;
  const std::size_t start = line_starts_[line_index];
  const std::size_t column =
      1 + (line_is_ascii_[line_index]
               ? offset - start
               : count_code_points(std::string_view(text_).substr(start, offset - start)));
  return {static_cast<std::uint32_t>(line_index + 1), static_cast<std::uint32_t>(column),
          static_cast<std::uint32_t>(offset)};
}

std::string_view SourceFile::line_text(std::uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  const std::size_t start = line_starts_[line - 1];
  std::size_t end = line < line_starts_.size() ? line_starts_[line] - 1 : text_.size();
  std::string_view view(text_);
  view = view.substr(start, end - start);
  if (!view.empty() && view.back() == '\r') view.remove_suffix(1);
  return view;
}

}  // namespace hlr::lang
