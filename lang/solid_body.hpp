// The items of a solid block — `vertex ID = POSITION`, `face ID ID ... [hole ID ...]...`, `line ID ID` —
// as flat arrays: generated scripts hold hundreds of thousands of them, and a node per item (let alone
// per number) cost 30 bytes of tree per byte of script. Vertex ids are interned per block, positions of
// three plain numbers are stored as numbers, and an item's place in the text is two byte offsets (the
// runtime turns them into a SourceSpan only for a message).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lang/source.hpp"

namespace hlr::lang {

struct Expr;

class SolidBody {
 public:
  enum class ItemKind : std::uint8_t { Vertex, Face, Line };
  struct Item {
    ItemKind kind = ItemKind::Vertex;
    std::uint32_t begin = 0;  // the item's text is [begin, end), byte offsets into the body's file
    std::uint32_t end = 0;
  };
  static constexpr std::uint32_t kLiteral = 0xffffffffu;
  struct Vertex {
    std::uint32_t id = 0;               // id(id) is its text
    std::uint32_t position = kLiteral;  // into positions(), or kLiteral: the point is `at`
    std::array<double, 3> at{};
  };

  SolidBody();
  explicit SolidBody(FileId file);
  SolidBody(SolidBody&&) noexcept;
  SolidBody& operator=(SolidBody&&) noexcept;
  ~SolidBody();

  FileId file() const { return file_; }

  // The vertex id `key` (a number by its value in decimal, so "01" is "1"; a name as written), its
  // index among this block's ids, added when new.
  std::uint32_t intern(std::string_view key);
  void add_vertex(std::uint32_t id, std::array<double, 3> at, std::uint32_t begin, std::uint32_t end);
  void add_vertex(std::uint32_t id, std::unique_ptr<Expr> position, std::uint32_t begin, std::uint32_t end);
  // A face: `refs` holds its rings back to back, ring r ending at ring_ends[r] (the outer ring first).
  void add_face(std::span<const std::uint32_t> refs, std::span<const std::uint32_t> ring_ends,
                std::uint32_t begin, std::uint32_t end);
  void add_line(std::uint32_t from, std::uint32_t to, std::uint32_t begin, std::uint32_t end);
  // The body, moved out with every array allocated to its size; this one is left empty for the next block
  // with its room kept. The parser reads every block into one body and keeps the copies.
  SolidBody take_compact();
  // Empties the body for a block of `file`, keeping its room.
  void restart(FileId file);

  // In the order written; the k-th Vertex item is vertices()[k], the k-th Face item face k, and so on.
  const std::vector<Item>& items() const { return items_; }
  std::size_t id_count() const { return id_ends_.size(); }
  std::string_view id(std::uint32_t k) const;
  const std::vector<Vertex>& vertices() const { return vertices_; }
  const Expr& position(const Vertex& v) const { return *positions_[v.position]; }
  std::size_t position_count() const { return positions_.size(); }
  const Expr& position_at(std::size_t k) const { return *positions_[k]; }

  std::size_t face_count() const { return face_ends_.size(); }
  std::size_t ring_count(std::size_t face) const { return face_ends_[face] - first_ring(face); }
  // Ring r (0: the outer ring, then the holes) of a face, as ids.
  std::span<const std::uint32_t> ring(std::size_t face, std::size_t r) const;
  const std::vector<std::array<std::uint32_t, 2>>& lines() const { return lines_; }
  std::size_t reference_count() const { return refs_.size(); }  // ids named by all faces' rings

 private:
  std::uint32_t first_ring(std::size_t face) const { return face == 0 ? 0 : face_ends_[face - 1]; }

  FileId file_ = 0;
  std::vector<Item> items_;
  std::string id_chars_;                                     // the ids back to back
  std::vector<std::uint32_t> id_ends_;                       // end of each id in id_chars_
  std::unordered_map<std::string, std::uint32_t> id_index_;  // while parsing a block with many ids
  std::vector<Vertex> vertices_;
  std::vector<std::unique_ptr<Expr>> positions_;
  std::vector<std::uint32_t> refs_;       // every ring of every face, back to back
  std::vector<std::uint32_t> ring_ends_;  // end of each ring in refs_
  std::vector<std::uint32_t> face_ends_;  // end of each face's rings in ring_ends_
  std::vector<std::array<std::uint32_t, 2>> lines_;
};

}  // namespace hlr::lang
