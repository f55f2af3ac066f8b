#include "core/plan/stroke_order.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "core/tolerance.hpp"

namespace hlr::plan {
namespace {

constexpr std::uint32_t kNone = ~0u;
constexpr double kGainEps = Tolerance::kPlanGain;
// A 2-opt or Or-opt move may rewrite at most this many tour positions (the shorter arc): windowed moves.
constexpr std::size_t kMaxRewrite = 25000;

Pt at(const std::vector<GridPoint>& vertices, std::uint32_t v) {
  return {static_cast<double>(vertices[v].x), static_cast<double>(vertices[v].y)};
}

class TourImprover {
 public:
  TourImprover(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices, const TourEnds& ends,
               std::size_t work_cap, const SharedNeighbours* shared)
      : strokes_(strokes), vertices_(vertices), ends_(ends), work_cap_(work_cap), shared_(shared) {
    n_ = strokes.size();
    N_ = n_ + 1;
    K = improve_list_length(n_) - 1;
    p0_.resize(N_);
    p1_.resize(N_);
    for (std::size_t s = 0; s < n_; ++s) set_ends(s);
    p0_[n_] = ends.end;  // the pseudo-stroke: entered at `end`, left at `start`
    p1_[n_] = ends.start;
    tour_.resize(N_);
    pos_.resize(N_);
    flip_.assign(N_, 0);
    tour_[0] = static_cast<std::uint32_t>(n_);
    for (std::size_t s = 0; s < n_; ++s) tour_[s + 1] = static_cast<std::uint32_t>(s);
    for (std::size_t i = 0; i < N_; ++i) pos_[tour_[i]] = static_cast<std::uint32_t>(i);
  }

  ImproveResult run() {
    // Neighbour lists built once; the second round starts from the re-entered closed strokes.
    build_neighbours();
    queued_.assign(N_, 0);
    queue_.clear();
    for (std::size_t i = 0; i < N_; ++i) touch(tour_[i]);
    for (int round = 0; round < 2; ++round) {
      local_search();
      const std::size_t rotated = reenter_closed();
      result_.moves += rotated;
      if (!rotated || stopped()) break;
    }
    write_back();
    return result_;
  }

 private:
  void set_ends(std::size_t s) {
    p0_[s] = at(vertices_, strokes_[s].vertices.front());
    p1_[s] = at(vertices_, strokes_[s].vertices.back());
  }
  bool is_free(std::uint32_t node) const { return ends_.end_free && node == 2 * n_; }
  Pt point(std::uint32_t node) const { return node & 1 ? p1_[node >> 1] : p0_[node >> 1]; }
  double d(std::uint32_t a, std::uint32_t b) const {
    return is_free(a) || is_free(b) ? 0.0 : dist(point(a), point(b));
  }
  std::size_t wrap(std::ptrdiff_t i) const {
    const auto n = static_cast<std::ptrdiff_t>(N_);
    return static_cast<std::size_t>(((i % n) + n) % n);
  }
  std::uint32_t entry(std::size_t position) const {
    const std::uint32_t s = tour_[wrap(static_cast<std::ptrdiff_t>(position))];
    return 2 * s + flip_[s];
  }
  std::uint32_t exit(std::size_t position) const {
    const std::uint32_t s = tour_[wrap(static_cast<std::ptrdiff_t>(position))];
    return 2 * s + 1 - flip_[s];
  }
  std::uint32_t entry_of(std::uint32_t s) const { return 2 * s + flip_[s]; }
  std::uint32_t exit_of(std::uint32_t s) const { return 2 * s + 1 - flip_[s]; }

  bool stopped() {
    if (result_.work < work_cap_) return false;
    result_.capped = true;
    return true;
  }

  // The lists from `shared_` when they cover exactly the stroke end points (see improve_order()).
  bool neighbours_from_shared() {
    if (!shared_ || !shared_->listed || !shared_->lists || shared_->k < K + 1 ||
        shared_->listed->size() != 2 * n_ || shared_->lists->size() != shared_->k * 2 * n_)
      return false;
    std::vector<std::uint32_t> node_of_vertex(vertices_.size(), kNone);
    for (std::size_t s = 0; s < n_; ++s) {
      if (strokes_[s].closed) return false;
      node_of_vertex[strokes_[s].vertices.front()] = static_cast<std::uint32_t>(2 * s);
      node_of_vertex[strokes_[s].vertices.back()] = static_cast<std::uint32_t>(2 * s + 1);
    }
    std::vector<std::uint32_t> node_of(shared_->listed->size());
    for (std::size_t i = 0; i < node_of.size(); ++i) {
      const std::uint32_t v = (*shared_->listed)[i];
      if (v >= vertices_.size() || node_of_vertex[v] == kNone) return false;
      node_of[i] = node_of_vertex[v];
    }
    nbr_.assign(2 * N_ * K, kNone);
    for (std::size_t i = 0; i < node_of.size(); ++i) {
      const std::uint32_t v = node_of[i];
      std::size_t k = 0;
      for (std::size_t m = 0; m < K + 1 && k < K; ++m) {
        const std::uint32_t c = (*shared_->lists)[i * shared_->k + m];
        if (c == kNone) break;
        if ((node_of[c] >> 1) != (v >> 1)) nbr_[v * K + k++] = node_of[c];
      }
    }
    // The pseudo-stroke's ends: the K nearest stroke ends by a scan (nearest first, ties by node).
    std::vector<std::pair<double, std::uint32_t>> near(2 * n_);
    for (std::uint32_t v = static_cast<std::uint32_t>(2 * n_); v < 2 * N_; ++v) {
      for (std::uint32_t c = 0; c < 2 * n_ && !is_free(v); ++c) near[c] = {dist2(point(v), point(c)), c};
      const auto m = static_cast<std::ptrdiff_t>(is_free(v) ? 0 : std::min(K, near.size()));
      std::partial_sort(near.begin(), near.begin() + m, near.end());
      for (std::ptrdiff_t k = 0; k < m; ++k)
        nbr_[v * K + static_cast<std::size_t>(k)] = near[static_cast<std::size_t>(k)].second;
      // ... and each in the lists of the stroke ends it is among the K nearest of, as a search over all
      // nodes would have it: moves that bring a stroke next to the start or the end come from those.
      for (std::uint32_t c = 0; c < 2 * n_ && !is_free(v); ++c) {
        std::uint32_t* list = &nbr_[c * K];
        const double dv = dist2(point(v), point(c));
        std::size_t at = K;
        while (at > 0 && (list[at - 1] == kNone || dist2(point(list[at - 1]), point(c)) > dv)) --at;
        if (at == K) continue;
        for (std::size_t j = K - 1; j > at; --j) list[j] = list[j - 1];
        list[at] = v;
      }
    }
    result_.work += 2 * N_ * 16;
    return true;
  }

  void build_neighbours() {
    if (neighbours_from_shared()) return;
    // All nodes but a free end; neighbours on the same stroke dropped.
    std::vector<Pt> pts;
    std::vector<std::uint32_t> node_of;
    pts.reserve(2 * N_);
    for (std::uint32_t v = 0; v < 2 * N_; ++v)
      if (!is_free(v)) pts.push_back(point(v)), node_of.push_back(v);
    std::vector<std::uint32_t> found;
    all_k_nearest(pts, K + 1, found, false);
    nbr_.assign(2 * N_ * K, kNone);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::uint32_t v = node_of[i];
      std::size_t k = 0;
      for (std::size_t m = 0; m <= K && k < K; ++m) {
        const std::uint32_t c = found[i * (K + 1) + m];
        if (c == kNone) break;
        if ((node_of[c] >> 1) != (v >> 1)) nbr_[v * K + k++] = node_of[c];
      }
    }
    result_.work += 2 * N_ * 16;
  }

  // Whether a move rewrites at most max_rewrite_ array elements (windowed 2-opt / Or-opt).
  bool affordable_reversal(std::size_t l, std::size_t r) const {
    const std::size_t len = wrap(static_cast<std::ptrdiff_t>(r) - static_cast<std::ptrdiff_t>(l)) + 1;
    return std::min(len, N_ - len) <= max_rewrite_;
  }
  bool affordable_move(std::size_t p, std::size_t len, std::size_t q) const {
    const std::size_t mid = wrap(static_cast<std::ptrdiff_t>(q) - static_cast<std::ptrdiff_t>(p + len)) + 1;
    return std::min(mid, N_ - len - mid) + len <= max_rewrite_;
  }

  // Reverses the strokes at positions l..r (circular), or the complementary arc — the same cycle.
  void reverse_block(std::size_t l, std::size_t r) {
    std::size_t len = wrap(static_cast<std::ptrdiff_t>(r) - static_cast<std::ptrdiff_t>(l)) + 1;
    if (2 * len > N_) {
      const std::size_t nl = wrap(static_cast<std::ptrdiff_t>(r) + 1);
      r = wrap(static_cast<std::ptrdiff_t>(l) - 1);
      l = nl;
      len = N_ - len;
    }
    for (std::size_t k = 0; k < len / 2; ++k) {
      const std::size_t i = wrap(static_cast<std::ptrdiff_t>(l + k)),
                        j = wrap(static_cast<std::ptrdiff_t>(r) - static_cast<std::ptrdiff_t>(k));
      std::swap(tour_[i], tour_[j]);
    }
    for (std::size_t k = 0; k < len; ++k) {
      const std::size_t i = wrap(static_cast<std::ptrdiff_t>(l + k));
      pos_[tour_[i]] = static_cast<std::uint32_t>(i);
      flip_[tour_[i]] ^= 1;
    }
    result_.work += len;
    touch_position(l), touch_position(r), touch_position(l - 1 + N_), touch_position(r + 1);
  }

  // Moves the `len` strokes starting at position p to just after position q (outside them), reversed or
  // not. The cycle is seg·mid·other; it becomes mid·seg'·other, rewriting the shorter arc.
  void move_segment(std::size_t p, std::size_t len, std::size_t q, bool reversed) {
    const std::size_t mid = wrap(static_cast<std::ptrdiff_t>(q) - static_cast<std::ptrdiff_t>(p + len)) + 1;
    const std::size_t other = N_ - len - mid;
    const std::uint32_t prev_s = tour_[wrap(static_cast<std::ptrdiff_t>(p) - 1)];
    const std::uint32_t next_s = tour_[wrap(static_cast<std::ptrdiff_t>(p + len))];
    buffer_.clear();
    auto push_seg = [&] {
      for (std::size_t k = 0; k < len; ++k)
        buffer_.push_back(tour_[wrap(static_cast<std::ptrdiff_t>(reversed ? p + len - 1 - k : p + k))]);
    };
    std::size_t start, seg_at;  // the rewritten arc's first position; the segment's new first position
    if (mid <= other) {
      start = p;
      for (std::size_t k = 0; k < mid; ++k)
        buffer_.push_back(tour_[wrap(static_cast<std::ptrdiff_t>(p + len + k))]);
      push_seg();
      seg_at = p + mid;
    } else {
      start = wrap(static_cast<std::ptrdiff_t>(q) + 1);
      push_seg();
      for (std::size_t k = 0; k < other; ++k)
        buffer_.push_back(tour_[wrap(static_cast<std::ptrdiff_t>(start + k))]);
      seg_at = start;
    }
    if (reversed)
      for (std::size_t k = 0; k < len; ++k) flip_[tour_[wrap(static_cast<std::ptrdiff_t>(p + k))]] ^= 1;
    for (std::size_t k = 0; k < buffer_.size(); ++k) {
      const std::size_t i = wrap(static_cast<std::ptrdiff_t>(start + k));
      tour_[i] = buffer_[k];
      pos_[buffer_[k]] = static_cast<std::uint32_t>(i);
    }
    result_.work += buffer_.size();
    touch(prev_s), touch(next_s);
    for (std::size_t k = 0; k < len; ++k) touch_position(seg_at + k);
    touch_position(seg_at + N_ - 1), touch_position(seg_at + len);
  }

  void touch(std::uint32_t s) {
    if (!queued_[s]) queued_[s] = 1, queue_.push_back(s);
  }
  void touch_position(std::size_t position) { touch(tour_[wrap(static_cast<std::ptrdiff_t>(position))]); }

  // 2-opt from node a: a new travel edge (a, c) for c among a's neighbours.
  bool try_two_opt(std::uint32_t a) {
    if (is_free(a)) return false;
    const std::uint32_t s = a >> 1;
    const std::size_t p = pos_[s];
    const bool a_exit = a == exit_of(s);
    const std::uint32_t b = a_exit ? entry(p + 1) : exit(p + N_ - 1);  // a's travel neighbour
    const double d_ab = d(a, b);
    for (std::size_t k = 0; k < K; ++k) {
      const std::uint32_t c = nbr_[a * K + k];
      if (c == kNone) break;
      ++result_.work;
      const double d_ac = d(a, c);
      if (d_ac >= d_ab - kGainEps) break;
      const std::uint32_t t = c >> 1;
      const std::size_t q = pos_[t];
      if (a_exit) {
        if (c != exit_of(t)) continue;
        const std::uint32_t cn = entry(q + 1);
        if (d_ac + d(b, cn) - d_ab - d(c, cn) < -kGainEps && affordable_reversal(p + 1, q)) {
          reverse_block(p + 1, q);
          return true;
        }
      } else {
        if (c != entry_of(t)) continue;
        const std::uint32_t cp = exit(q + N_ - 1);
        if (d_ac + d(b, cp) - d_ab - d(cp, c) < -kGainEps && affordable_reversal(p, q + N_ - 1)) {
          reverse_block(p, q + N_ - 1);
          return true;
        }
      }
    }
    return false;
  }

  // Or-opt: move the 1–3 strokes starting at stroke s's position next to a neighbour of their ends.
  bool try_or_opt(std::uint32_t s) {
    const std::size_t p = pos_[s];
    for (std::size_t len = 1; len <= 3 && len + 2 <= N_; ++len) {
      const std::size_t prev = wrap(static_cast<std::ptrdiff_t>(p) - 1),
                        next = wrap(static_cast<std::ptrdiff_t>(p + len));
      const std::uint32_t a = entry(p), b = exit(p + len - 1);
      const std::uint32_t xp = exit(prev), en = entry(next);
      const double removed = d(xp, a) + d(b, en) - d(xp, en);
      if (removed <= kGainEps) continue;
      for (int end = 0; end < 2; ++end) {
        const std::uint32_t node = end ? b : a;
        if (is_free(node)) continue;
        for (std::size_t k = 0; k < K; ++k) {
          const std::uint32_t c = nbr_[node * K + k];
          if (c == kNone) break;
          ++result_.work;
          const double d_nc = d(node, c);
          if (d_nc >= removed - kGainEps) break;
          const std::uint32_t t = c >> 1;
          const std::size_t q = pos_[t];
          if (wrap(static_cast<std::ptrdiff_t>(q) - static_cast<std::ptrdiff_t>(p)) < len)
            continue;             // inside
          if (c == exit_of(t)) {  // insert after q
            if (q == prev) continue;
            const std::uint32_t cn = entry(q + 1);
            const double added = d_nc + d(end ? a : b, cn) - d(c, cn);
            if (added - removed < -kGainEps && affordable_move(p, len, q)) {
              move_segment(p, len, q, end == 1);
              return true;
            }
          } else {  // insert before q
            if (q == next) continue;
            const std::uint32_t cp = exit(q + N_ - 1);
            const double added = d(cp, end ? a : b) + d_nc - d(cp, c);
            if (added - removed < -kGainEps &&
                affordable_move(p, len, wrap(static_cast<std::ptrdiff_t>(q) - 1))) {
              move_segment(p, len, wrap(static_cast<std::ptrdiff_t>(q) - 1), end == 0);
              return true;
            }
          }
        }
      }
    }
    return false;
  }

  void local_search() {
    while (!queue_.empty() && !stopped()) {
      const std::uint32_t s = queue_.front();
      queue_.pop_front();
      queued_[s] = 0;
      if (try_two_opt(exit_of(s)) || try_two_opt(entry_of(s)) || try_or_opt(s)) {
        ++result_.moves;
        touch(s);
      }
    }
  }

  // Enters every closed stroke at the vertex nearest its neighbours in the tour; returns how many moved.
  std::size_t reenter_closed() {
    std::size_t moved = 0;
    for (std::size_t i = 0; i < N_; ++i) {
      const std::uint32_t s = tour_[i];
      if (s == n_ || !strokes_[s].closed) continue;
      const std::uint32_t xp = exit(i + N_ - 1), en = entry(i + 1);
      const std::vector<std::uint32_t>& v = strokes_[s].vertices;
      auto cost = [&](std::size_t k) {
        const Pt p = at(vertices_, v[k]);
        return (is_free(xp) ? 0.0 : dist(point(xp), p)) + (is_free(en) ? 0.0 : dist(p, point(en)));
      };
      double best = cost(0);
      std::size_t best_k = 0;
      for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        const double c = cost(k);
        if (c < best - kGainEps) best = c, best_k = k;
      }
      result_.work += v.size();
      if (best_k) {
        rotate_closed(strokes_[s], best_k);
        set_ends(s);
        ++moved;
        touch(s), touch_position(i + N_ - 1), touch_position(i + 1);
      }
    }
    return moved;
  }

  // Reads the cycle from the pseudo-stroke, in the direction that leaves `start` first.
  void write_back() {
    std::vector<GridStroke> out;
    out.reserve(n_);
    const std::size_t home = pos_[n_];
    const bool backwards = flip_[n_];
    for (std::size_t k = 1; k < N_; ++k) {
      const std::size_t i = backwards
                                ? wrap(static_cast<std::ptrdiff_t>(home) - static_cast<std::ptrdiff_t>(k))
                                : wrap(static_cast<std::ptrdiff_t>(home + k));
      const std::uint32_t s = tour_[i];
      GridStroke g = std::move(strokes_[s]);
      if (flip_[s] != backwards) std::reverse(g.vertices.begin(), g.vertices.end());
      out.push_back(std::move(g));
    }
    strokes_ = std::move(out);
  }

  std::vector<GridStroke>& strokes_;
  const std::vector<GridPoint>& vertices_;
  TourEnds ends_;
  std::size_t work_cap_;
  const SharedNeighbours* shared_;
  std::size_t max_rewrite_ = kMaxRewrite;
  std::size_t K = 8;
  std::size_t n_ = 0, N_ = 0;
  std::vector<Pt> p0_, p1_;  // per stroke: first and last point in its stored orientation
  std::vector<std::uint32_t> tour_, pos_;
  std::vector<std::uint8_t> flip_;
  std::vector<std::uint32_t> nbr_;
  std::vector<std::uint32_t> buffer_;
  std::deque<std::uint32_t> queue_;
  std::vector<std::uint8_t> queued_;
  ImproveResult result_;
};

}  // namespace

std::size_t improve_list_length(std::size_t strokes) {
  // K neighbours per stroke end (the list also holds the end itself or its stroke's other end): 5, or
  // more for small tours, where a wider search costs little.
  const std::size_t nodes = strokes + 1;
  return 1 + (nodes <= 64 ? 31 : (nodes <= 16384 ? 8 : 5));
}

double tour_travel(const std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                   const TourEnds& ends) {
  double total = 0;
  Pt here = ends.start;
  for (const GridStroke& s : strokes) {
    total += dist(here, at(vertices, s.vertices.front()));
    here = at(vertices, s.vertices.back());
  }
  if (!ends.end_free) total += dist(here, ends.end);
  return total;
}

void order_greedy(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                  const TourEnds& ends) {
  // Every way into a stroke: both ends of an open one, every vertex of a closed one.
  struct Entry {
    std::uint32_t stroke, index;
  };
  std::vector<Entry> entries;
  std::vector<Pt> points;
  std::vector<std::uint32_t> first(strokes.size() + 1);
  for (std::uint32_t s = 0; s < strokes.size(); ++s) {
    first[s] = static_cast<std::uint32_t>(entries.size());
    const std::vector<std::uint32_t>& v = strokes[s].vertices;
    if (strokes[s].closed) {
      for (std::uint32_t k = 0; k + 1 < v.size(); ++k) entries.push_back({s, k});
    } else {
      entries.push_back({s, 0});
      entries.push_back({s, static_cast<std::uint32_t>(v.size() - 1)});
    }
  }
  first[strokes.size()] = static_cast<std::uint32_t>(entries.size());
  points.reserve(entries.size());
  for (const Entry& e : entries) points.push_back(at(vertices, strokes[e.stroke].vertices[e.index]));
  std::vector<std::uint8_t> closed(strokes.size());
  for (std::size_t i = 0; i < strokes.size(); ++i) closed[i] = strokes[i].closed;
  // The search touches only the tree and the entry arrays; the strokes are moved afterwards.
  KdTree tree(points);
  std::vector<std::uint32_t> chosen;
  chosen.reserve(strokes.size());
  Pt here = ends.start;
  std::uint32_t near = kNone;  // the entry where the pen stands (drawn): its leaf starts the next search
  while (tree.alive()) {
    const std::uint32_t found = near == kNone ? tree.nearest(here) : tree.nearest(here, near);
    const Entry e = entries[found];
    for (std::uint32_t k = first[e.stroke]; k < first[e.stroke + 1]; ++k) tree.erase(k);
    near = closed[e.stroke] ? found : (e.index ? first[e.stroke] : first[e.stroke] + 1);
    here = points[near];
    chosen.push_back(found);
  }
  std::vector<GridStroke> out;
  out.reserve(strokes.size());
  for (std::uint32_t found : chosen) {
    const Entry e = entries[found];
    GridStroke s = std::move(strokes[e.stroke]);
    if (s.closed)
      rotate_closed(s, e.index);
    else if (e.index)
      std::reverse(s.vertices.begin(), s.vertices.end());
    out.push_back(std::move(s));
  }
  strokes = std::move(out);
}

void order_circuits(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                    const TourEnds& ends) {
  // Circuits as ranges [begin, end) of the strokes.
  std::vector<std::uint32_t> begin{0};
  for (std::uint32_t i = 1; i < strokes.size(); ++i)
    if (strokes[i].circuit != strokes[i - 1].circuit) begin.push_back(i);
  begin.push_back(static_cast<std::uint32_t>(strokes.size()));
  const std::size_t circuits = begin.size() - 1;
  std::vector<std::uint32_t> circuit_of(strokes.size());
  for (std::uint32_t c = 0; c < circuits; ++c)
    for (std::uint32_t i = begin[c]; i < begin[c + 1]; ++i) circuit_of[i] = c;
  // Entries: every stroke's front (the circuit forwards from it) and back (backwards from it); a closed
  // stroke alone in its circuit at every vertex.
  struct Entry {
    std::uint32_t stroke, index;  // index: vertex of a closed stroke; else 0 = front, 1 = back
  };
  std::vector<Entry> entries;
  std::vector<Pt> points;
  std::vector<std::uint32_t> first(circuits + 1);
  for (std::uint32_t c = 0; c < circuits; ++c) {
    first[c] = static_cast<std::uint32_t>(entries.size());
    for (std::uint32_t i = begin[c]; i < begin[c + 1]; ++i) {
      const std::vector<std::uint32_t>& v = strokes[i].vertices;
      if (strokes[i].closed) {
        for (std::uint32_t k = 0; k + 1 < v.size(); ++k) entries.push_back({i, k});
      } else {
        entries.push_back({i, 0});
        entries.push_back({i, 1});
      }
    }
  }
  first[circuits] = static_cast<std::uint32_t>(entries.size());
  points.reserve(entries.size());
  for (const Entry& e : entries) {
    const GridStroke& s = strokes[e.stroke];
    points.push_back(
        at(vertices, s.closed ? s.vertices[e.index] : (e.index ? s.vertices.back() : s.vertices.front())));
  }
  KdTree tree(points);
  std::vector<GridStroke> out;
  out.reserve(strokes.size());
  Pt here = ends.start;
  std::uint32_t near = kNone;  // the last circuit's entry: it ends by the virtual edge dropped there
  while (tree.alive()) {
    near = near == kNone ? tree.nearest(here) : tree.nearest(here, near);
    const Entry e = entries[near];
    const std::uint32_t c = circuit_of[e.stroke];
    for (std::uint32_t k = first[c]; k < first[c + 1]; ++k) tree.erase(k);
    const std::uint32_t b = begin[c], n = begin[c + 1] - b, j = e.stroke - b;
    for (std::uint32_t k = 0; k < n; ++k) {
      GridStroke& s = strokes[b + (e.index && !strokes[e.stroke].closed ? (j + n - k) % n : (j + k) % n)];
      if (s.closed)
        rotate_closed(s, k == 0 ? e.index : 0);
      else if (e.index)
        std::reverse(s.vertices.begin(), s.vertices.end());
      out.push_back(std::move(s));
    }
    here = at(vertices, out.back().vertices.back());
  }
  strokes = std::move(out);
}

ImproveResult improve_order(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                            const TourEnds& ends, std::size_t work_per_stroke,
                            const SharedNeighbours* shared) {
  if (strokes.empty()) return {};
  TourImprover improver(strokes, vertices, ends, work_per_stroke * (strokes.size() + 1), shared);
  return improver.run();
}

}  // namespace hlr::plan
