// A union of closed parameter intervals inside [0, 1]: the hidden parts of one edge.
#pragma once

#include <algorithm>
#include <vector>

namespace hlr {

struct Interval {
  double lo = 0, hi = 0;
};

class IntervalSet {
 public:
  void clear() { items_.clear(); }
  bool empty() const { return items_.empty(); }
  // The intervals as added (until a call that normalises): overlaps kept, for counting them.
  const std::vector<Interval>& items() const { return items_; }
  void add(double lo, double hi) {
    if (hi <= lo) return;
    items_.push_back({std::max(lo, 0.0), std::min(hi, 1.0)});
  }
  // Sorts and merges overlapping or touching intervals; returns the normalised list.
  const std::vector<Interval>& normalize() {
    std::sort(items_.begin(), items_.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    std::size_t out = 0;
    for (const Interval& iv : items_) {
      if (out > 0 && iv.lo <= items_[out - 1].hi) {
        items_[out - 1].hi = std::max(items_[out - 1].hi, iv.hi);
      } else {
        items_[out++] = iv;
      }
    }
    items_.resize(out);
    return items_;
  }
  // Normalises, then also joins neighbours whose gap is negligible: gap_is_small(hi, next_lo) decides.
  template <typename GapIsSmall>
  const std::vector<Interval>& close_gaps(GapIsSmall&& gap_is_small) {
    normalize();
    std::size_t out = 0;
    for (std::size_t i = 0; i < items_.size(); ++i) {
      if (out > 0 && gap_is_small(items_[out - 1].hi, items_[i].lo)) {
        items_[out - 1].hi = std::max(items_[out - 1].hi, items_[i].hi);
      } else {
        items_[out++] = items_[i];
      }
    }
    items_.resize(out);
    return items_;
  }
  // Removes intervals for which is_negligible(lo, hi) holds (after normalising).
  template <typename IsNegligible>
  void drop(IsNegligible&& is_negligible) {
    normalize();
    std::erase_if(items_, [&](const Interval& iv) { return is_negligible(iv.lo, iv.hi); });
  }
  // True when the (normalised) set covers [0, 1] entirely.
  bool covers_all() {
    normalize();
    return items_.size() == 1 && items_[0].lo <= 0 && items_[0].hi >= 1;
  }
  // The complement in [lo, hi] of the normalised set.
  std::vector<Interval> complement(double lo = 0, double hi = 1) {
    std::vector<Interval> out;
    complement_into(out, lo, hi);
    return out;
  }
  // The same into `out` (cleared first), whose room is reused.
  void complement_into(std::vector<Interval>& out, double lo = 0, double hi = 1) {
    normalize();
    out.clear();
    double cursor = lo;
    for (const Interval& iv : items_) {
      if (iv.lo > cursor) out.push_back({cursor, std::min(iv.lo, hi)});
      cursor = std::max(cursor, iv.hi);
      if (cursor >= hi) break;
    }
    if (cursor < hi) out.push_back({cursor, hi});
  }

 private:
  std::vector<Interval> items_;
};

}  // namespace hlr
