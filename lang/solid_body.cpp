#include "lang/solid_body.hpp"

#include <algorithm>
#include <iterator>

#include "lang/ast.hpp"

namespace hlr::lang {

namespace {
// Blocks with at most this many ids (a box has 8) find them by comparing: no hash table per block.
constexpr std::size_t kFewIds = 16;
}  // namespace

SolidBody::SolidBody() = default;
SolidBody::SolidBody(FileId file) : file_(file) {}
SolidBody::SolidBody(SolidBody&&) noexcept = default;
SolidBody& SolidBody::operator=(SolidBody&&) noexcept = default;
SolidBody::~SolidBody() = default;

std::string_view SolidBody::id(std::uint32_t k) const {
  const std::uint32_t from = k == 0 ? 0 : id_ends_[k - 1];
  return std::string_view(id_chars_).substr(from, id_ends_[k] - from);
}

std::uint32_t SolidBody::intern(std::string_view key) {
  const std::size_t count = id_ends_.size();
  if (count <= kFewIds) {
    for (std::uint32_t k = 0; k < count; ++k)
      if (id(k) == key) return k;
  } else {
    if (id_index_.empty())
      for (std::uint32_t k = 0; k < count; ++k) id_index_.emplace(std::string(id(k)), k);
    const auto it = id_index_.find(std::string(key));
    if (it != id_index_.end()) return it->second;
  }
  const auto index = static_cast<std::uint32_t>(count);
  id_chars_.append(key);
  id_ends_.push_back(static_cast<std::uint32_t>(id_chars_.size()));
  if (!id_index_.empty()) id_index_.emplace(std::string(key), index);
  return index;
}

void SolidBody::add_vertex(std::uint32_t id, std::array<double, 3> at, std::uint32_t begin,
                           std::uint32_t end) {
  items_.push_back({ItemKind::Vertex, begin, end});
  vertices_.push_back({id, kLiteral, at});
}

void SolidBody::add_vertex(std::uint32_t id, std::unique_ptr<Expr> position, std::uint32_t begin,
                           std::uint32_t end) {
  items_.push_back({ItemKind::Vertex, begin, end});
  vertices_.push_back({id, static_cast<std::uint32_t>(positions_.size()), {}});
  positions_.push_back(std::move(position));
}

void SolidBody::add_face(std::span<const std::uint32_t> refs, std::span<const std::uint32_t> ring_ends,
                         std::uint32_t begin, std::uint32_t end) {
  items_.push_back({ItemKind::Face, begin, end});
  const auto base = static_cast<std::uint32_t>(refs_.size());
  refs_.insert(refs_.end(), refs.begin(), refs.end());
  for (const std::uint32_t e : ring_ends) ring_ends_.push_back(base + e);
  face_ends_.push_back(static_cast<std::uint32_t>(ring_ends_.size()));
}

void SolidBody::add_line(std::uint32_t from, std::uint32_t to, std::uint32_t begin, std::uint32_t end) {
  items_.push_back({ItemKind::Line, begin, end});
  lines_.push_back({from, to});
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
  SolidBody out(file_);
  out.items_ = exact_copy(items_);
  out.id_chars_ = std::string(id_chars_);
  id_chars_.clear();
  out.id_ends_ = exact_copy(id_ends_);
  id_index_.clear();
  out.vertices_ = exact_copy(vertices_);
  out.positions_ = exact_copy(positions_);
  out.refs_ = exact_copy(refs_);
  out.ring_ends_ = exact_copy(ring_ends_);
  out.face_ends_ = exact_copy(face_ends_);
  out.lines_ = exact_copy(lines_);
  return out;
}

void SolidBody::restart(FileId file) {
  file_ = file;
  items_.clear();
  id_chars_.clear();
  id_ends_.clear();
  id_index_.clear();
  vertices_.clear();
  positions_.clear();
  refs_.clear();
  ring_ends_.clear();
  face_ends_.clear();
  lines_.clear();
}

std::span<const std::uint32_t> SolidBody::ring(std::size_t face, std::size_t r) const {
  const std::size_t ring = first_ring(face) + r;
  const std::size_t from = ring == 0 ? 0 : ring_ends_[ring - 1];
  return {refs_.data() + from, ring_ends_[ring] - from};
}

}  // namespace hlr::lang
