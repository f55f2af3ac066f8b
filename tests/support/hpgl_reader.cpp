#include "tests/support/hpgl_reader.hpp"

#include <cmath>
#include <cstdlib>

namespace hlr::test {

HpglParse parse_hpgl(std::string_view text) {
  HpglParse out;
  std::size_t i = 0;
  const auto fail = [&](const std::string& what) {
    out.error = what + " at byte " + std::to_string(i);
    return out;
  };
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  while (i < text.size()) {
    if (text[i] == '\n') {  // a newline may follow any command
      if (i == 0 || text[i - 1] != ';') return fail("newline not after a ';'");
      ++i;
      continue;
    }
    if (i + 2 > text.size() || !(text[i] >= 'A' && text[i] <= 'Z') ||
        !(text[i + 1] >= 'A' && text[i + 1] <= 'Z'))
      return fail("expected a two-letter mnemonic");
    HpglCommand c;
    c.mnemonic = std::string(text.substr(i, 2));
    i += 2;
    bool first = true;
    while (i < text.size() && text[i] != ';') {
      if (!first) {
        if (text[i] != ',') return fail("expected ',' or ';' in " + c.mnemonic);
        ++i;
      }
      first = false;
      const std::size_t start = i;
      if (i < text.size() && text[i] == '-') ++i;
      const std::size_t digits = i;
      while (i < text.size() && is_digit(text[i])) ++i;
      if (i == digits) return fail("expected a number in " + c.mnemonic);
      if (i < text.size() && text[i] == '.') {
        c.integers = false;
        ++i;
        const std::size_t frac = i;
        while (i < text.size() && is_digit(text[i])) ++i;
        if (i == frac) return fail("expected digits after '.' in " + c.mnemonic);
      }
      c.params.push_back(std::strtod(std::string(text.substr(start, i - start)).c_str(), nullptr));
    }
    if (i >= text.size()) return fail("missing ';' after " + c.mnemonic);
    ++i;  // ';'
    out.commands.push_back(std::move(c));
  }
  return out;
}

HpglReplay replay_hpgl(const std::vector<HpglCommand>& commands) {
  HpglReplay r;
  bool absolute = true, down = false, known = false;
  int pen = 0;
  HpglPos at;
  const auto close_run = [&] { down = false; };
  for (std::size_t k = 0; k < commands.size() && r.error.empty(); ++k) {
    const HpglCommand& c = commands[k];
    const std::string where = " (command " + std::to_string(k + 1) + ", " + c.mnemonic + ")";
    for (double v : c.params)
      if (v < -32768 || v > 32767) r.error = "number " + std::to_string(v) + " beyond ±32767" + where;
    if (!r.error.empty()) break;
    if (c.mnemonic == "IN" || c.mnemonic == "DF") {
      if (!c.params.empty()) r.error = "parameters" + where;
      absolute = true;
      close_run();
      if (c.mnemonic == "IN") pen = 0;
    } else if (c.mnemonic == "VS") {
      if (c.params.size() != 1)
        r.error = "VS takes one parameter" + where;
      else
        r.velocity = c.params[0];
    } else if (c.mnemonic == "SP") {
      if (c.params.size() > 1 || !c.integers) r.error = "SP takes one integer" + where;
      pen = c.params.empty() ? 0 : static_cast<int>(c.params[0]);
      r.pens_selected.push_back(pen);
      close_run();
    } else if (c.mnemonic == "PA" || c.mnemonic == "PR") {
      if (!c.params.empty()) r.error = "parameters" + where;  // the device never moves with PA/PR
      absolute = c.mnemonic == "PA";
    } else if (c.mnemonic == "PU" || c.mnemonic == "PD") {
      if (c.params.size() % 2 != 0 || !c.integers) {
        r.error = "odd or fractional coordinates" + where;
        break;
      }
      const bool pd = c.mnemonic == "PD";
      if (pd && pen <= 0) {
        r.error = "drawing with no pen selected" + where;
        break;
      }
      if (!pd) close_run();
      if (pd && !down) {
        if (!known) {
          r.error = "pen down at an unknown position" + where;
          break;
        }
        down = true;
        r.runs.push_back({pen, {at}});
      }
      for (std::size_t j = 0; j < c.params.size(); j += 2) {
        const long x = static_cast<long>(c.params[j]), y = static_cast<long>(c.params[j + 1]);
        if (absolute) {
          at = {x, y};
          known = true;
        } else {
          if (!known) {
            r.error = "relative move before any absolute position" + where;
            break;
          }
          at = {at.x + x, at.y + y};
        }
        if (at.x < -32768 || at.x > 32767 || at.y < -32768 || at.y > 32767)
          r.error = "position beyond ±32767" + where;
        r.visited.push_back(at);
        if (pd) r.runs.back().points.push_back(at);
      }
    } else {
      r.error = "unexpected command" + where;
    }
  }
  r.absolute_at_end = absolute;
  r.pen_up_at_end = !down;
  return r;
}

HpglReplay read_hpgl(std::string_view text) {
  const HpglParse p = parse_hpgl(text);
  if (!p.error.empty()) {
    HpglReplay r;
    r.error = p.error;
    return r;
  }
  return replay_hpgl(p.commands);
}

}  // namespace hlr::test
