// Vertex stage of SolidBuilder::build(): interned ids, the vertex table, and the checks on vertices
// (non-finite coordinates, duplicate ids, two ids at one position).
#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>

#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {

// ---- IdTable ---------------------------------------------------------------------------------------------

std::size_t IdTable::slot_of(std::string_view id, std::size_t hash) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t s = hash & mask;; s = (s + 1) & mask)
    if (slots_[s] == 0 || text(slots_[s] - 1) == id) return s;
}

void IdTable::grow() {
  std::vector<std::uint32_t> old = std::move(slots_);
  slots_.assign(std::max<std::size_t>(16, 2 * old.size()), 0);
  for (std::uint32_t number : old)
    if (number != 0) {
      const std::string_view id = text(number - 1);
      slots_[slot_of(id, std::hash<std::string_view>{}(id))] = number;
    }
}

std::uint32_t IdTable::intern(std::string_view id) {
  if (2 * (ends_.size() + 1) > slots_.size()) grow();
  const std::size_t s = slot_of(id, std::hash<std::string_view>{}(id));
  if (slots_[s] != 0) return slots_[s] - 1;
  chars_ += id;
  ends_.push_back(chars_.size());
  slots_[s] = size();
  return size() - 1;
}

std::uint32_t IdTable::find(std::string_view id) const {
  if (slots_.empty()) return kNone;
  const std::uint32_t number = slots_[slot_of(id, std::hash<std::string_view>{}(id))];
  return number == 0 ? kNone : number - 1;
}

// ---- VertexTable -----------------------------------------------------------------------------------------

namespace {

bool indexed(const std::vector<std::uint32_t>& input_ids, VertexIndex input) {
  return input_ids.empty() || input_ids[input] == IdTable::kNone;
}

}  // namespace

VertexIndex VertexTable::resolve(VertexRef ref) const {
  if (!(ref & kIndexRef)) return by_id[ref];
  // Indexed: the id is the number in decimal. Only if some id was given as text can another vertex
  // carry it (or the vertex with that number have another id).
  const VertexIndex input = ref & ~kIndexRef;
  if (!by_id.empty()) {
    const std::uint32_t named = ids->find(std::to_string(input));
    if (named != IdTable::kNone) return by_id[named];
  }
  if (input >= input_count || !indexed(*input_ids, input)) return kNoVertex;
  return table_of.empty() ? input : table_of[input];
}

std::string VertexTable::ref_text(VertexRef ref) const {
  if (!(ref & kIndexRef)) return std::string(ids->text(ref));
  const VertexIndex input = ref & ~kIndexRef;
  return label && input < input_count ? (*label)(input) : std::to_string(input);
}

std::string VertexTable::id(VertexIndex v) const {
  const VertexIndex input = input_of.empty() ? v : input_of[v];
  if (!indexed(*input_ids, input)) return std::string(ids->text((*input_ids)[input]));
  return label ? (*label)(input) : std::to_string(input);
}

// ---- the vertex stage ------------------------------------------------------------------------------------

namespace {

// Earliest vertex within the tolerance of each vertex (n = none). Points are binned into cubic cells of
// twice the tolerance: a point then has neighbours within the tolerance only in its own cell and, per
// axis, the adjacent cell on the side of the nearer cell border: 8 cells to look in. Coordinates are at
// most 1e9 tolerances from the origin. Nearly every cell holds one point, so a first pass in vertex order
// asks two small bitmaps of the cells met so far (a Bloom filter: no false negatives) and keeps only the
// few vertices with a possible earlier neighbour; a second pass collects the points in the cells those
// ask about and checks them exactly. Both stay in cache, unlike a hash map of the cells.
std::vector<VertexIndex> earlier_twins(const VertexTable& table) {
  const std::vector<Point3>& pos = table.positions();
  const std::size_t n = pos.size();
  const double tol = table.tolerance.length, cell = 2 * tol;
  struct Cell {
    std::int64_t c[3];
    bool operator==(const Cell&) const = default;
  };
  auto cell_of = [&](Point3 p) {
    Cell c;
    for (int k = 0; k < 3; ++k) c.c[k] = static_cast<std::int64_t>(std::floor(p[k] / cell));
    return c;
  };
  // The 8 cells to look in around p: its own first.
  auto near_cells = [&](Point3 p, Cell out[8]) {
    const Cell c = cell_of(p);
    std::int64_t side[3];
    for (int k = 0; k < 3; ++k) side[k] = p[k] / cell - std::floor(p[k] / cell) < 0.5 ? -1 : 1;
    for (int corner = 0; corner < 8; ++corner) {
      out[corner] = c;
      for (int k = 0; k < 3; ++k)
        if (corner & (1 << k)) out[corner].c[k] += side[k];
    }
  };
  auto hash_of = [](const Cell& c) {
    std::uint64_t h = static_cast<std::uint64_t>(c.c[0]) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(c.c[1]) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(c.c[2]) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return h * 0x9E3779B97F4A7C15ull;
  };
  const std::size_t bits = 8 * std::bit_ceil(std::max<std::size_t>(n, 8));  // per bitmap
  const int shift = 64 - std::countr_zero(bits);
  auto bit1 = [&](std::uint64_t h) { return h >> shift; };
  auto bit2 = [&](std::uint64_t h) { return ((h ^ (h >> 31)) * 0xD6E8FEB86659FD93ull) >> shift; };
  auto test = [](const std::vector<std::uint64_t>& map, std::uint64_t b) {
    return (map[b / 64] >> (b % 64)) & 1;
  };
  auto set = [](std::vector<std::uint64_t>& map, std::uint64_t b) {
    map[b / 64] |= std::uint64_t{1} << (b % 64);
  };

  std::vector<std::uint64_t> seen1(bits / 64, 0), seen2(bits / 64, 0), wanted(bits / 64, 0);
  std::vector<VertexIndex> suspects;
  Cell near[8];
  for (std::size_t i = 0; i < n; ++i) {
    if (!table.usable[i]) continue;
    near_cells(pos[i], near);
    bool suspect = false;
    for (const Cell& c : near) {
      const std::uint64_t h = hash_of(c);
      if (test(seen1, bit1(h)) && test(seen2, bit2(h))) {
        suspect = true;
        set(wanted, bit1(h));
      }
    }
    if (suspect) suspects.push_back(static_cast<VertexIndex>(i));
    const std::uint64_t h = hash_of(near[0]);
    set(seen1, bit1(h));
    set(seen2, bit2(h));
  }
  seen1 = std::vector<std::uint64_t>();  // (= {} would keep the capacity)
  seen2 = std::vector<std::uint64_t>();

  std::vector<VertexIndex> twin(n, static_cast<VertexIndex>(n));
  if (suspects.empty()) return twin;
  std::vector<std::pair<std::uint64_t, VertexIndex>> members;  // (cell hash, vertex) in wanted cells
  for (std::size_t j = 0; j < n; ++j) {
    if (!table.usable[j]) continue;
    const std::uint64_t h = hash_of(cell_of(pos[j]));
    if (test(wanted, bit1(h))) members.emplace_back(h, static_cast<VertexIndex>(j));
  }
  std::sort(members.begin(), members.end());
  for (VertexIndex i : suspects) {
    near_cells(pos[i], near);
    for (const Cell& c : near) {
      const std::uint64_t h = hash_of(c);
      auto it = std::lower_bound(members.begin(), members.end(), std::pair<std::uint64_t, VertexIndex>{h, 0});
      for (; it != members.end() && it->first == h; ++it) {
        const VertexIndex j = it->second;
        if (j >= i || j >= twin[i]) break;  // ascending: the first hit is the earliest
        if (cell_of(pos[j]) == c && distance(pos[i], pos[j]) <= tol) {
          twin[i] = j;
          break;
        }
      }
    }
  }
  return twin;
}

}  // namespace

VertexTable resolve_vertices(const std::vector<Point3>& positions, Tags tags,
                             const std::vector<std::uint32_t>& input_ids, const IdTable& ids,
                             const std::function<std::string(VertexIndex)>* label, Diagnostics& diagnostics) {
  VertexTable table;
  table.label = label;
  table.input_ids = &input_ids;
  table.ids = &ids;
  const std::size_t n = positions.size();
  table.input_count = n;
  table.input_positions = &positions;
  table.usable.reserve(n);
  table.by_id.assign(ids.size(), kNoVertex);
  auto skipped = [&] { return !table.table_of.empty(); };
  for (std::size_t i = 0; i < n; ++i) {
    const auto t = static_cast<VertexIndex>(table.usable.size());
    // The interned id, if some face, line or vertex gave it as text.
    std::uint32_t named = IdTable::kNone;
    if (!indexed(input_ids, static_cast<VertexIndex>(i)))
      named = input_ids[i];
    else if (ids.size() > 0)
      named = ids.find(std::to_string(i));
    if (named != IdTable::kNone && table.by_id[named] != kNoVertex) {
      diagnostics.error(
          "duplicate-vertex",
          "vertex '" + std::string(ids.text(named)) + "' is declared twice; give each vertex its own id",
          tags[i]);
      if (!skipped()) {  // from here on, indices and input numbers differ
        table.table_of.resize(i);
        table.input_of.resize(i);
        for (std::size_t k = 0; k < i; ++k)
          table.table_of[k] = table.input_of[k] = static_cast<VertexIndex>(k);
        table.kept.assign(positions.begin(), positions.begin() + static_cast<std::ptrdiff_t>(i));
      }
      table.table_of.push_back(table.by_id[named]);
      continue;
    }
    if (named != IdTable::kNone) table.by_id[named] = t;
    if (skipped()) {
      table.table_of.push_back(t);
      table.input_of.push_back(static_cast<VertexIndex>(i));
    }
    const Point3 p = positions[i];
    const bool finite = is_finite(p);
    if (!finite) {
      const double bad = !std::isfinite(p.x) ? p.x : (!std::isfinite(p.y) ? p.y : p.z);
      diagnostics.error(
          "non-finite",
          "vertex '" + table.id(t) + "' has a non-finite coordinate (" + format_for_message(bad) + ")",
          tags[i]);
    }
    if (skipped()) table.kept.push_back(p);
    table.usable.push_back(finite);
  }

  double extent = 0;
  for (std::size_t i = 0; i < table.usable.size(); ++i)
    if (table.usable[i])
      for (int k = 0; k < 3; ++k) extent = std::max(extent, std::abs(table.positions()[i][k]));
  table.tolerance = Tolerance::for_extent(extent);
  return table;
}

void report_vertex_twins(const VertexTable& table, Tags tags, Diagnostics& diagnostics) {
  const std::vector<VertexIndex> twin = earlier_twins(table);
  for (std::size_t i = 0; i < twin.size(); ++i)
    if (twin[i] < twin.size())
      diagnostics.error("duplicate-vertex",
                        "vertex '" + table.id(static_cast<VertexIndex>(i)) +
                            "' is at the same position as vertex '" + table.id(twin[i]) + "'",
                        tags[table.input_of.empty() ? i : table.input_of[i]]);
}

}  // namespace hlr::solid_detail
