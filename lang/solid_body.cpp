#include "lang/solid_body.hpp"

#include <algorithm>
#include <iterator>

#include "lang/ast.hpp"

namespace hlr::lang {

namespace {
// Blocks with at most this many ids (a box has 8) find them by comparing: no hash table per block.
constexpr std::size_t kFewIds = 16;
}  // namespace

const SolidBody::Parts SolidBody::kNoParts{};

SolidBody::SolidBody() : parts_(std::make_unique<Parts>()) {}
SolidBody::SolidBody(FileId file) : parts_(std::make_unique<Parts>()) { parts_->file = file; }
SolidBody::SolidBody(SolidBody&&) noexcept = default;
SolidBody& SolidBody::operator=(SolidBody&&) noexcept = default;
SolidBody::~SolidBody() = default;

SolidBody::Parts& SolidBody::own() {
  if (!parts_) parts_ = std::make_unique<Parts>();
  return *parts_;
}

std::string_view SolidBody::id(std::uint32_t k) const {
  const Parts& p = parts();
  const std::uint32_t from = k == 0 ? 0 : p.id_ends[k - 1];
  return std::string_view(p.id_chars).substr(from, p.id_ends[k] - from);
}

std::uint32_t SolidBody::intern(std::string_view key) {
  Parts& p = own();
  const std::size_t count = p.id_ends.size();
  if (count <= kFewIds) {
    for (std::uint32_t k = 0; k < count; ++k)
      if (id(k) == key) return k;
  } else {
    if (p.id_index.empty())
      for (std::uint32_t k = 0; k < count; ++k) p.id_index.emplace(std::string(id(k)), k);
    const auto it = p.id_index.find(std::string(key));
    if (it != p.id_index.end()) return it->second;
  }
  const auto index = static_cast<std::uint32_t>(count);
  p.id_chars.append(key);
  p.id_ends.push_back(static_cast<std::uint32_t>(p.id_chars.size()));
  if (!p.id_index.empty()) p.id_index.emplace(std::string(key), index);
  return index;
}

void SolidBody::add_vertex(std::uint32_t id, std::array<double, 3> at, std::uint32_t begin,
                           std::uint32_t end) {
  Parts& p = own();
  p.items.push_back({ItemKind::Vertex, begin, end});
  p.vertices.push_back({id, kLiteral, at});
}

void SolidBody::add_vertex(std::uint32_t id, std::unique_ptr<Expr> position, std::uint32_t begin,
                           std::uint32_t end) {
  Parts& p = own();
  p.items.push_back({ItemKind::Vertex, begin, end});
  p.vertices.push_back({id, static_cast<std::uint32_t>(p.positions.size()), {}});
  p.positions.push_back(std::move(position));
}

void SolidBody::add_face(std::span<const std::uint32_t> refs, std::span<const std::uint32_t> ring_ends,
                         std::uint32_t begin, std::uint32_t end) {
  Parts& p = own();
  p.items.push_back({ItemKind::Face, begin, end});
  const auto base = static_cast<std::uint32_t>(p.refs.size());
  p.refs.insert(p.refs.end(), refs.begin(), refs.end());
  for (const std::uint32_t e : ring_ends) p.ring_ends.push_back(base + e);
  p.face_ends.push_back(static_cast<std::uint32_t>(p.ring_ends.size()));
}

void SolidBody::add_line(std::uint32_t from, std::uint32_t to, std::uint32_t begin, std::uint32_t end) {
  Parts& p = own();
  p.items.push_back({ItemKind::Line, begin, end});
  p.lines.push_back({from, to});
}

namespace {
template <typename T>
std::vector<T> exact_copy(std::vector<T>& from) {
  std::vector<T> out;
  out.reserve(from.size());
  std::move(from.begin(), from.end(), std::back_inserter(out));
  from.clear();
  return out;
}
}  // namespace

SolidBody SolidBody::take_compact() {
  Parts& p = own();
  SolidBody out(p.file);
  Parts& q = *out.parts_;
  q.items = exact_copy(p.items);
  q.id_chars = std::string(p.id_chars);
  p.id_chars.clear();
  q.id_ends = exact_copy(p.id_ends);
  p.id_index.clear();
  q.vertices = exact_copy(p.vertices);
  q.positions = exact_copy(p.positions);
  q.refs = exact_copy(p.refs);
  q.ring_ends = exact_copy(p.ring_ends);
  q.face_ends = exact_copy(p.face_ends);
  q.lines = exact_copy(p.lines);
  return out;
}

void SolidBody::restart(FileId file) {
  Parts& p = own();
  p.file = file;
  p.items.clear();
  p.id_chars.clear();
  p.id_ends.clear();
  p.id_index.clear();
  p.vertices.clear();
  p.positions.clear();
  p.refs.clear();
  p.ring_ends.clear();
  p.face_ends.clear();
  p.lines.clear();
}

std::span<const std::uint32_t> SolidBody::ring(std::size_t face, std::size_t r) const {
  const Parts& p = parts();
  const std::size_t ring = first_ring(face) + r;
  const std::size_t from = ring == 0 ? 0 : p.ring_ends[ring - 1];
  return {p.refs.data() + from, p.ring_ends[ring] - from};
}

}  // namespace hlr::lang
