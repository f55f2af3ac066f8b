// Ctrl-C while the REPL works. Its SIGINT handler sets the flag; evaluation (Budget::step) and the
// engine (HlrOptions::cancel, set by every render) check it and stop with RenderCancelled, and the REPL
// clears it before each input. Only the REPL installs a handler: elsewhere Ctrl-C ends the process as
// usual and the flag stays false. A plain atomic flag is what a signal handler may touch.
#pragma once

#include <atomic>

namespace hlr::runtime {

inline std::atomic<bool>& interrupt_requested() {
  static std::atomic<bool> flag{false};
  return flag;
}

}  // namespace hlr::runtime
