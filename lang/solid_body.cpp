#include "lang/solid_body.hpp"

#include <algorithm>

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

std::uint32_t SolidBody::intern(std::string_view key) {
  if (ids_.size() <= kFewIds) {
    for (std::size_t i = 0; i < ids_.size(); ++i)
      if (ids_[i] == key) return static_cast<std::uint32_t>(i);
  } else {
    if (id_index_.empty())
      for (std::size_t i = 0; i < ids_.size(); ++i) id_index_.emplace(ids_[i], static_cast<std::uint32_t>(i));
    const auto it = id_index_.find(std::string(key));
    if (it != id_index_.end()) return it->second;
  }
  const auto index = static_cast<std::uint32_t>(ids_.size());
  ids_.emplace_back(key);
  if (!id_index_.empty()) id_index_.emplace(ids_.back(), index);
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

std::span<const std::uint32_t> SolidBody::ring(std::size_t face, std::size_t r) const {
  const std::size_t ring = first_ring(face) + r;
  const std::size_t from = ring == 0 ? 0 : ring_ends_[ring - 1];
  return {refs_.data() + from, ring_ends_[ring] - from};
}

}  // namespace hlr::lang
