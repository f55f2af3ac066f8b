// How a drawing shows what the solids hide: not at all, as one dashed layer, or by occlusion level — the
// hidden pieces behind 1, 2, … `levels` surfaces, each level a layer (and with a hidden pen, a pen) of
// its own. `style hidden off|dashed|levels N`, `--hidden`, `--levels N` and the REPL's `:hidden` and
// `:levels` all set one of these.
#pragma once

#include <string>

#include "core/limits.hpp"

namespace hlr {

struct HiddenStyle {
  enum class Mode { Off, Dashed, Levels };
  Mode mode = Mode::Off;
  int levels = 0;  // Levels: the deepest level drawn, 1..kMaxOcclusionLevel; else 0

  static HiddenStyle off() { return {}; }
  static HiddenStyle dashed() { return {Mode::Dashed, 0}; }
  static HiddenStyle counted(int levels) { return {Mode::Levels, levels}; }

  bool drawn() const { return mode != Mode::Off; }
  bool counts_levels() const { return mode == Mode::Levels; }
  // HlrOptions::max_level: the levels the engine is to count, 0 when it counts none.
  unsigned max_level() const { return counts_levels() ? static_cast<unsigned>(levels) : 0U; }
  // The statement's words after `style hidden`: "off", "dashed", "levels 3".
  std::string words() const {
    return mode == Mode::Off ? "off" : mode == Mode::Dashed ? "dashed" : "levels " + std::to_string(levels);
  }

  friend bool operator==(const HiddenStyle&, const HiddenStyle&) = default;
};

// Whether n is a number of levels that can be drawn.
inline bool valid_level_count(long long n) { return n >= 1 && n <= kMaxOcclusionLevel; }

}  // namespace hlr
