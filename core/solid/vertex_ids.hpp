// SolidBuilder's vertex ids, interned: each distinct text is stored once and numbered in first-use order,
// so faces and lines hold 4-byte numbers instead of strings. Not part of the public API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::solid_detail {

// How a face or line names a vertex: the number of an interned id, or kIndexRef | vertex number
// (indexed input, id = the number in decimal).
using VertexRef = std::uint32_t;
inline constexpr VertexRef kIndexRef = 0x80000000u;

struct LineSpec {  // an add_line line
  VertexRef a, b;
  std::int64_t tag;
};

class IdTable {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  std::uint32_t intern(std::string_view id);      // its number, added if new
  std::uint32_t find(std::string_view id) const;  // kNone if never interned
  std::string_view text(std::uint32_t number) const {
    const std::size_t begin = number == 0 ? 0 : ends_[number - 1];
    return std::string_view(chars_).substr(begin, ends_[number] - begin);
  }
  std::uint32_t size() const { return static_cast<std::uint32_t>(ends_.size()); }

 private:
  // The slot holding `id`, or the empty one it would take.
  std::size_t slot_of(std::string_view id, std::size_t hash) const;
  void grow();

  std::string chars_;              // all ids, back to back
  std::vector<std::size_t> ends_;  // end of each id in chars_
  // Open addressing: number + 1, 0 = empty; a power of two, at most half full.
  std::vector<std::uint32_t> slots_;
};

}  // namespace hlr::solid_detail
