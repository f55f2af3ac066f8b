// A small HP-GL reader for tests, written independently of the HPGL device: a strict parser for the
// command syntax the device promises (two capital letters, numbers separated by single commas, `;`,
// optionally a newline) and an interpreter for IN, DF, VS, SP, PU, PD, PA and PR that replays the pen.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::test {

struct HpglCommand {
  std::string mnemonic;        // "PD"
  std::vector<double> params;  // as written
  bool integers = true;        // every parameter written without a fraction
};

struct HpglParse {
  std::vector<HpglCommand> commands;
  std::string error;  // empty when the text is well formed; else what is wrong and where
};

HpglParse parse_hpgl(std::string_view text);

struct HpglPos {
  long x = 0, y = 0;
  bool operator==(const HpglPos&) const = default;
};

// One pen-down run: from the position where the pen went down through every pair drawn. A dot is a run
// whose points are all equal.
struct HpglRun {
  int pen = 0;
  std::vector<HpglPos> points;
};

struct HpglReplay {
  std::vector<HpglRun> runs;
  std::vector<HpglPos> visited;    // every position the pen reached, up or down, in order
  std::optional<double> velocity;  // the last VS
  std::vector<int> pens_selected;  // SP parameters in order (0 included)
  bool absolute_at_end = true;     // PA mode when the file ends
  bool pen_up_at_end = true;
  std::string error;  // empty when the replay found nothing wrong (unknown command, number beyond
                      // ±32767, a relative move before any absolute one, drawing with no pen, …)
};

HpglReplay replay_hpgl(const std::vector<HpglCommand>& commands);

// parse + replay; the error of either.
HpglReplay read_hpgl(std::string_view text);

}  // namespace hlr::test
