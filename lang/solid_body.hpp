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

  FileId file() const { return parts().file; }

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
  const std::vector<Item>& items() const { return parts().items; }
  std::size_t id_count() const { return parts().id_ends.size(); }
  std::string_view id(std::uint32_t k) const;
  const std::vector<Vertex>& vertices() const { return parts().vertices; }
  const Expr& position(const Vertex& v) const { return *parts().positions[v.position]; }
  std::size_t position_count() const { return parts().positions.size(); }
  const Expr& position_at(std::size_t k) const { return *parts().positions[k]; }

  std::size_t face_count() const { return parts().face_ends.size(); }
  std::size_t ring_count(std::size_t face) const { return parts().face_ends[face] - first_ring(face); }
  // Ring r (0: the outer ring, then the holes) of a face, as ids.
  std::span<const std::uint32_t> ring(std::size_t face, std::size_t r) const;
  const std::vector<std::array<std::uint32_t, 2>>& lines() const { return parts().lines; }
  std::size_t reference_count() const { return parts().refs.size(); }  // ids named by all faces' rings

 private:
  std::uint32_t first_ring(std::size_t face) const { return face == 0 ? 0 : parts().face_ends[face - 1]; }

  // The arrays live behind one pointer: a statement holding a SolidBody stays small (a script's
  // statements are a vector of variants as large as their largest kind, and this was 288 bytes of it).
  struct Parts {
    FileId file = 0;
    std::vector<Item> items;
    std::string id_chars;                                     // the ids back to back
    std::vector<std::uint32_t> id_ends;                       // end of each id in id_chars
    std::unordered_map<std::string, std::uint32_t> id_index;  // while parsing a block with many ids
    std::vector<Vertex> vertices;
    std::vector<std::unique_ptr<Expr>> positions;
    std::vector<std::uint32_t> refs;       // every ring of every face, back to back
    std::vector<std::uint32_t> ring_ends;  // end of each ring in refs
    std::vector<std::uint32_t> face_ends;  // end of each face's rings in ring_ends
    std::vector<std::array<std::uint32_t, 2>> lines;
  };
  static const Parts kNoParts;  // what a moved-from body reads as
  const Parts& parts() const { return parts_ ? *parts_ : kNoParts; }
  Parts& own();  // the parts, made when missing

  std::unique_ptr<Parts> parts_;
};

}  // namespace hlr::lang
